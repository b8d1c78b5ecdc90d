// Structural similarity (SSIM; Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality
// assessment: from error visibility to structural similarity"): a perceptual error measure
// beside RMSE, for image_diff and tools/speed_accuracy.
//
// As in the paper: an 11x11 Gaussian window of sigma 1.5 (normalised to sum 1), K1 = 0.01,
// K2 = 0.03, population (not sample) variances. Computed on each RGB channel separately and
// the three mean SSIMs averaged (scikit-image's structural_similarity with channel_axis,
// gaussian_weights=True, sigma=1.5, use_sample_covariance=False). The mean is over the
// pixels whose whole window lies inside the image (5 pixels in from each edge), so no edge
// rule enters; scikit-image crops the same border.
#pragma once

#include "base/float_image.h"

inline constexpr int kSsimWindow = 11; // pixels a side; images must be at least this large

// Mean SSIM of a against b; dataRange is L, the span of the values (1 for float images in
// [0,1], 255 for bytes). Throws std::invalid_argument if the sizes differ or a side is
// under kSsimWindow.
double structuralSimilarity(const ImageF& a, const ImageF& b, double dataRange);
