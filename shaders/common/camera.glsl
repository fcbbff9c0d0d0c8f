// Pinhole camera ray, docs/estimator.md "Camera" (render/reference/cpu_camera.cpp is the CPU twin).
// forward/right/up are the orthonormal camera axes; y = 0 is the top row.
#ifndef WAVELIT_CAMERA_GLSL
#define WAVELIT_CAMERA_GLSL

vec3 cameraDirection(vec3 forward, vec3 right, vec3 up, float tanHalf, float aspect, uvec2 size,
                     uvec2 pixel, float u, float v) {
    float sx = (2.0 * (float(pixel.x) + u) / float(size.x) - 1.0) * tanHalf * aspect;
    float sy = (1.0 - 2.0 * (float(pixel.y) + v) / float(size.y)) * tanHalf;
    return normalize(forward + sx * right + sy * up);
}

#endif
