// When the path tracer's image is better than the preview (issue 13 hand-over; docs/relighting.md
// §6). Neither error is known without a converged reference, but both can be estimated from what
// the editor has after a few tracer passes: the preview P, the tracer's running mean M, and the
// variance of that mean per pixel V (σ²/spp; varianceOfMean estimates it from two independent
// half-sample means). With the relative metric of render/session/image_metrics.h (mean over
// pixels and channels of (x - ref)^2 / (ref^2 + 1e-2)), scaled by the preview's value (it is
// noise-free; a noisy tracer mean in the denominator blows up where a pixel's mean is near 0):
//   E[relMSE(P, M)] ≈ e_P + e_M,  e_M = mean of V / (P^2 + 1e-2),
// because the tracer's noise is independent of the preview's error e_P (direct lighting only,
// the grid's resolution). So e_P ≈ relMSE(P, M) - e_M, and the tracer is better once e_M < e_P,
// i.e. 2 e_M < relMSE(P, M). Both are returned as relative RMSEs (sqrt), comparable with the
// relRMSE figures of `wavelit-cli relight` and `bench` (tests: within 10% of the true errors).
#pragma once

#include "util/image.h"

namespace wavelit::relight {

struct HandOverEstimate {
    double previewRelRmse = 0.0; // the preview's estimated error against the converged image
    double tracerRelRmse = 0.0;  // the tracer's estimated error (its noise)
    bool tracerBetter = false;   // tracerRelRmse < previewRelRmse: show the tracer
};

// preview, tracerMean and meanVariance: the same size (meanVariance per channel, >= 0). The
// preview at another size is compared by nearest pixel. An empty image gives tracerBetter false.
HandOverEstimate estimateHandOver(const util::ImageRGB& preview, const util::ImageRGB& tracerMean,
                                  const util::ImageRGB& meanVariance);

// The variance of the mean (a + b) / 2 of two independent half-sample means, per pixel and
// channel: ((a - b) / 2)^2 (unbiased: E[(a - b)^2] = 2 Var(a), Var of the mean = Var(a) / 2).
util::ImageRGB varianceOfMean(const util::ImageRGB& halfA, const util::ImageRGB& halfB);

} // namespace wavelit::relight
