#include "compare/ssim.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr int kRadius = kSsimWindow / 2;
constexpr double kSigma = 1.5, kK1 = 0.01, kK2 = 0.03;

// The window's 1-D weights, exp(-x^2 / (2 sigma^2)) normalised to sum 1; the 2-D window is
// their outer product.
std::array<double, kSsimWindow> gaussianWeights() {
    std::array<double, kSsimWindow> weights{};
    double sum = 0;
    for (int k = -kRadius; k <= kRadius; ++k) {
        weights[std::size_t(k + kRadius)] = std::exp(-0.5 * k * k / (kSigma * kSigma));
        sum += weights[std::size_t(k + kRadius)];
    }
    for (double& w : weights)
        w /= sum;
    return weights;
}

// The Gaussian-weighted mean of a plane around every pixel whose window is inside the
// image: (width - 10) x (height - 10) values, filtered along x and then along y.
std::vector<double> windowMeans(const std::vector<double>& plane, int width, int height) {
    static const std::array<double, kSsimWindow> weights = gaussianWeights();
    const int innerWidth = width - 2 * kRadius, innerHeight = height - 2 * kRadius;
    std::vector<double> alongX(std::size_t(innerWidth) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < innerWidth; ++x) {
            double sum = 0;
            for (int k = 0; k < kSsimWindow; ++k)
                sum += weights[std::size_t(k)] * plane[std::size_t(y) * width + std::size_t(x + k)];
            alongX[std::size_t(y) * innerWidth + std::size_t(x)] = sum;
        }
    std::vector<double> means(std::size_t(innerWidth) * std::size_t(innerHeight));
    for (int y = 0; y < innerHeight; ++y)
        for (int x = 0; x < innerWidth; ++x) {
            double sum = 0;
            for (int k = 0; k < kSsimWindow; ++k)
                sum += weights[std::size_t(k)] *
                       alongX[std::size_t(y + k) * innerWidth + std::size_t(x)];
            means[std::size_t(y) * innerWidth + std::size_t(x)] = sum;
        }
    return means;
}

// Mean SSIM of one channel.
double channelSsim(const ImageF& a, const ImageF& b, int channel, double dataRange) {
    const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);
    std::vector<double> x(pixels), y(pixels), xx(pixels), yy(pixels), xy(pixels);
    for (std::size_t p = 0; p < pixels; ++p) {
        x[p] = a.rgb[p * 3 + std::size_t(channel)];
        y[p] = b.rgb[p * 3 + std::size_t(channel)];
        xx[p] = x[p] * x[p];
        yy[p] = y[p] * y[p];
        xy[p] = x[p] * y[p];
    }
    const std::vector<double> mx = windowMeans(x, a.width, a.height);
    const std::vector<double> my = windowMeans(y, a.width, a.height);
    const std::vector<double> mxx = windowMeans(xx, a.width, a.height);
    const std::vector<double> myy = windowMeans(yy, a.width, a.height);
    const std::vector<double> mxy = windowMeans(xy, a.width, a.height);
    const double c1 = (kK1 * dataRange) * (kK1 * dataRange);
    const double c2 = (kK2 * dataRange) * (kK2 * dataRange);
    double sum = 0;
    for (std::size_t k = 0; k < mx.size(); ++k) {
        const double varianceX = mxx[k] - mx[k] * mx[k];
        const double varianceY = myy[k] - my[k] * my[k];
        const double covariance = mxy[k] - mx[k] * my[k];
        sum += (2 * mx[k] * my[k] + c1) * (2 * covariance + c2) /
               ((mx[k] * mx[k] + my[k] * my[k] + c1) * (varianceX + varianceY + c2));
    }
    return sum / double(mx.size());
}

} // namespace

double structuralSimilarity(const ImageF& a, const ImageF& b, double dataRange) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("image sizes differ: " + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " vs " + std::to_string(b.width) +
                                    "x" + std::to_string(b.height));
    if (a.width < kSsimWindow || a.height < kSsimWindow)
        throw std::invalid_argument("SSIM needs images of at least " + std::to_string(kSsimWindow) +
                                    "x" + std::to_string(kSsimWindow) + " pixels");
    for (const ImageF* image : {&a, &b})
        if (image->rgb.size() != std::size_t(image->width) * std::size_t(image->height) * 3)
            throw std::invalid_argument("image buffer does not match its size");
    if (!(dataRange > 0)) throw std::invalid_argument("SSIM's data range must be positive");
    double sum = 0;
    for (int channel = 0; channel < 3; ++channel)
        sum += channelSsim(a, b, channel, dataRange);
    return sum / 3.0;
}
