// SSIM (tools/reference/ssim.h) on cases whose value follows from the definition by hand;
// tests/tools/ssim_skimage_test.py checks it against scikit-image on general images.
//
// With a window w (weights summing to 1) the local statistics are mu = sum w x,
// sigma^2 = sum w x^2 - mu^2, sigma_xy = sum w x y - mu_x mu_y, and
//   SSIM = (2 mu_x mu_y + C1)(2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 +
//   C2))
// with C1 = (0.01 L)^2, C2 = (0.03 L)^2.
#include "compare/ssim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace {

ImageF constantImage(int width, int height, float r, float g, float b) {
    ImageF image{width, height, {}};
    for (int p = 0; p < width * height; ++p)
        image.rgb.insert(image.rgb.end(), {r, g, b});
    return image;
}

ImageF noiseImage(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    ImageF image{width, height, {}};
    for (int k = 0; k < width * height * 3; ++k)
        image.rgb.push_back(unit(random));
    return image;
}

// Flat images: every variance and covariance is 0, so the second factor is C2 / C2 = 1
// and SSIM = (2 a b + C1) / (a^2 + b^2 + C1) per channel.
double flatSsim(double a, double b, double dataRange) {
    const double c1 = (0.01 * dataRange) * (0.01 * dataRange);
    return (2 * a * b + c1) / (a * a + b * b + c1);
}

} // namespace

TEST(Ssim, IdenticalImagesGiveExactlyOne) {
    const ImageF image = noiseImage(40, 31, 1);
    EXPECT_EQ(structuralSimilarity(image, image, 1.0), 1.0);
    const ImageF bytes = imageFromBytes(quantizeImage(image));
    EXPECT_EQ(structuralSimilarity(bytes, bytes, 255.0), 1.0);
}

TEST(Ssim, ConstantOffsetOfAFlatImageHasTheClosedForm) {
    const ImageF a = constantImage(16, 12, 0.2f, 0.5f, 0.9f);
    const ImageF b = constantImage(16, 12, 0.25f, 0.4f, 0.9f);
    const double expected =
        (flatSsim(0.2f, 0.25f, 1.0) + flatSsim(0.5f, 0.4f, 1.0) + flatSsim(0.9f, 0.9f, 1.0)) / 3;
    EXPECT_NEAR(structuralSimilarity(a, b, 1.0), expected, 1e-12);
    // In bytes, L = 255: 51 against 64.
    const ImageF c = constantImage(11, 11, 51, 51, 51), d = constantImage(11, 11, 64, 64, 64);
    EXPECT_NEAR(structuralSimilarity(c, d, 255.0), flatSsim(51, 64, 255), 1e-12);
}

// b = a + d on a textured a: in every window sigma_b^2 = sigma_ab = sigma_a^2, so the
// second factor is 1 and SSIM = (2 mu (mu + d) + C1) / (mu^2 + (mu + d)^2 + C1), mu the
// window's mean of a. On a checkerboard of 0.4 and 0.6 that mean is 0.5 + 0.1 s^2 or
// 0.5 - 0.1 s^2, s the alternating sum of the 1-D weights (sum (-1)^k w_k, about 3e-5 for
// sigma 1.5): 0.5 to within 1e-9. Left: the rounding of b's floats (about 1e-8).
TEST(Ssim, ConstantOffsetOfATexturedImageOnlyLowersTheLuminanceTerm) {
    ImageF a{24, 20, {}};
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 24; ++x) {
            const float v = (x + y) % 2 ? 0.6f : 0.4f;
            a.rgb.insert(a.rgb.end(), {v, v, v});
        }
    ImageF b = a;
    const double d = 0.1;
    for (float& v : b.rgb)
        v = float(v + d);
    const double c1 = 0.01 * 0.01, mu = 0.5;
    const double expected = (2 * mu * (mu + d) + c1) / (mu * mu + (mu + d) * (mu + d) + c1);
    EXPECT_NEAR(structuralSimilarity(a, b, 1.0), expected, 1e-6);
    EXPECT_LT(structuralSimilarity(a, b, 1.0), 0.99); // 0.9836: well off 1
}

TEST(Ssim, IsSymmetricAndFallsWithNoise) {
    const ImageF a = noiseImage(30, 30, 2);
    ImageF slightly = a, strongly = a;
    std::mt19937 random(3);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    for (std::size_t k = 0; k < a.rgb.size(); ++k) {
        const float n = noise(random);
        slightly.rgb[k] += 0.01f * n;
        strongly.rgb[k] += 0.2f * n;
    }
    EXPECT_EQ(structuralSimilarity(a, slightly, 1.0), structuralSimilarity(slightly, a, 1.0));
    EXPECT_GT(structuralSimilarity(a, slightly, 1.0), structuralSimilarity(a, strongly, 1.0));
    EXPECT_LT(structuralSimilarity(a, slightly, 1.0), 1.0);
}

TEST(Ssim, RejectsSmallOrMismatchedImages) {
    EXPECT_THROW(structuralSimilarity(noiseImage(10, 20, 1), noiseImage(10, 20, 1), 1.0),
                 std::invalid_argument);
    EXPECT_THROW(structuralSimilarity(noiseImage(12, 12, 1), noiseImage(12, 13, 1), 1.0),
                 std::invalid_argument);
    EXPECT_NO_THROW(structuralSimilarity(noiseImage(11, 11, 1), noiseImage(11, 11, 2), 1.0));
}
