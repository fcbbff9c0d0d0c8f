// One path of the CPU reference tracer, written down term by term (issue 20's outlier tracer):
// CpuPathTracer::samplePixel fills it when given one, and `wavelit-cli render --trace-outliers`
// writes the records of the largest samples as JSON (outlier_tracer.h).
//
// Vertices are the scattering/hit points in path order. Events are the radiance the path found,
// each attached to the vertex whose technique drew the direction that found it (-1: the camera
// ray). Per event: what found it (kind), the technique that drew the direction, its pdf, every
// pdf that enters the MIS weight, the weight, f·cos at the drawing vertex, the radiance found,
// the throughput before the drawing vertex, and the contribution added to the pixel's sample.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace wavelit::render {

struct PathPdf {
    std::string name; // "bsdf", "env", "product", "cosine", "uniform", "mixture", "light", ...
    double value = 0.0;
};

struct PathEvent {
    int vertex = -1;        // the vertex that drew the direction (-1: camera ray)
    std::string kind;       // emission | env-escape | env-nee | light-nee | light-hit
    std::string technique;  // the technique that drew the direction
    double pdf = 0.0;       // its solid-angle pdf (0: not applicable)
    std::vector<PathPdf> misPdfs; // the pdfs that enter the MIS weight
    double weight = 1.0;          // the MIS weight applied
    glm::vec3 fcos{0.0f};         // f·cos at the drawing vertex (1 for camera rays)
    glm::vec3 radiance{0.0f};     // radiance found along the direction
    glm::vec3 throughput{0.0f};   // path throughput before the drawing vertex's factor
    glm::vec3 contribution{0.0f}; // added to the sample
};

struct PathVertex {
    int depth = 0;
    std::string material;
    glm::vec3 position{0.0f};
    glm::vec3 throughputIn{0.0f}; // beta arriving at the vertex
    // The continuation drawn here (empty technique: the path ended at this vertex).
    std::string technique;
    double pdf = 0.0;             // the pdf the estimator divides by
    std::vector<PathPdf> pdfs;    // the techniques' pdfs at the continuation direction ("env",
                                  // ...; "share:env": that technique's mixture weight)
    glm::vec3 fcos{0.0f};
    double continueProbability = 1.0; // Russian roulette's survival probability (1: none)
    glm::vec3 throughputOut{0.0f}; // beta after f·cos/pdf and Russian roulette
    std::string end;               // why the path stopped here, if it did
};

struct PathRecord {
    int x = 0, y = 0, pass = 0;
    glm::vec3 value{0.0f}; // the sample
    std::vector<PathVertex> vertices;
    std::vector<PathEvent> events;
};

} // namespace wavelit::render
