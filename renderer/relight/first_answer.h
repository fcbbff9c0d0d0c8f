// The corrected first answer of coarse-to-fine (issue 13, docs/relighting.md §7.0c). During a drag
// the full preview is behind, but most of its image is still right: an object drag changes the
// image only where the object's shadow, reflection or silhouette moves. So the first answer is the
// full image from before the pending edits ("then"), corrected by what the coarse preview says
// changed, per full-resolution pixel i and its nearest coarse point c:
//   - the pixel's camera hit is unchanged: fine_then(i) + coarse_now(c) - coarse_then(c), clamped
//     at 0 (the shadow or reflection that moved, at the coarse grid's resolution; where c itself
//     now sees another surface, fine_then(i) alone). A ratio (coarse_now + e) / (coarse_then + e)
//     instead of the difference was measured and is worse (§7.0c);
//   - it now hits a moved object: the same object point before the move, projected into the
//     camera, where the full image saw it (same object, same depth): fine_then there;
//   - anything else (a surface the object uncovered): coarse_now(c).
// Only pixels next to a coarse point whose hit changed need their hit re-cast (one camera ray
// each; no visibility rays). It is an APPROXIMATION, labelled as such wherever it is shown
// (`firstAnswer: approximate` in the CLI's report): its error against the exact full preview is
// measured (§7.0c) and bounded by a test; the full answer (applyFine) stays exact.
#pragma once

#include "relight/relight_preview.h"
#include "util/image.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace wavelit::relight {

// What the full and the coarse preview showed when the full one was last brought up to date.
struct FirstAnswerBase {
    util::ImageRGB fine;                  // the full preview's image() (its own resolution)
    std::vector<PreviewPoint> finePoints; // its camera hits
    util::ImageRGB coarse;                // the coarse preview's image()
    std::vector<PreviewPoint> coarsePoints;
    std::vector<glm::mat4> objects;       // each object's transform matrix
};
FirstAnswerBase firstAnswerBase(const RelightPreview& fine, const RelightPreview& coarse);

// The first answer at width x height (computed at the full preview's resolution, then scaled
// by nearest pixel); `coarseNow` is the coarse preview after the pending edits.
util::ImageRGB correctedFirstAnswer(const FirstAnswerBase& then, const RelightPreview& coarseNow, int width,
                                    int height);

// `image` scaled to width x height by nearest pixel (RelightPreview::image's mapping).
util::ImageRGB nearestScaled(const util::ImageRGB& image, int width, int height);

// sqrt of render/session/image_metrics.h's relative MSE (the same formula: squared difference over
// reference^2 + 0.01, averaged over pixels and channels); relight may not link render.
double relativeRmse(const util::ImageRGB& image, const util::ImageRGB& reference);

} // namespace wavelit::relight
