#ifndef WAVELIT_CONSTANTS_GLSL
#define WAVELIT_CONSTANTS_GLSL
const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kFourPi = 4.0 * kPi; // the sphere's solid angle
const float kFloatMax = 3.402823466e38;
// "No hit" sentinel of the box test: GLSL has no constant infinity, and no finite entry distance
// reaches FLT_MAX because every query's tMax is at most FLT_MAX.
const float kInfinity = kFloatMax;
#endif
