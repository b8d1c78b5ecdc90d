#include "compare/global_search.h"

#include "base/parallel.h"
#include "reference/reference_renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

using glm::dvec3;

namespace {

constexpr long kSamplePixels = 20000;
constexpr int kMaxDepth = 5; // the depths searched: 0 to the model's default

// A candidate whose share of close sample pixels is this near the best one's is as good:
// then the one with the fewest departures from the defaults is taken, so that JPEG noise,
// a symmetric scene or a difference in a handful of pixels names no setting. The further
// the best is from matching, the larger a gain must be to count: an image of another
// scene, or with many mistakes of its own, is not explained by settings that each gain
// a little.
double shareSlack(double best) {
    return 0.002 + 0.05 * (1.0 - best);
}

// The brightness factors the search believes: beyond them the image is not the scene
// scaled but another picture, which a factor only seems to explain.
constexpr double kLowestBrightness = 0.5, kHighestBrightness = 2.0;

} // namespace

std::vector<glm::ivec2> searchSamplePixels(int width, int height) {
    const long pixels = long(width) * long(height);
    const int stride =
        std::max(1, int(std::ceil(std::sqrt(double(pixels) / double(kSamplePixels)))));
    std::vector<glm::ivec2> samples;
    for (int j = stride / 2; j < height; j += stride)
        for (int i = stride / 2; i < width; i += stride)
            samples.emplace_back(i, j);
    return samples;
}

namespace {

// The number with the fewest decimals (0 to 3) that an image under settings shows within
// window levels of value's level (0: the same level).
double shortestEquivalent(const GlobalSettings& settings, double value, double window) {
    const double level = presentedLevel(settings, value);
    for (double scale : {1.0, 10.0, 100.0, 1000.0}) {
        const double candidate = std::round(value * scale) / scale;
        if (std::abs(presentedLevel(settings, candidate) - level) <= window) return candidate;
    }
    return std::round(value * 1000.0) / 1000.0;
}

struct Candidate {
    GlobalSettings settings;
    double close = 0;     // the share of sample pixels whose channels are all close
    double meanError = 0; // mean absolute channel difference, levels
};

// What every candidate is held to: the user's fixed settings, how near a level counts as
// the same, and the channel orders to try.
struct SearchRules {
    const FixedSettings& fixed;
    double closeness;
    std::vector<std::array<int, 3>> orders;
};

template <typename T> std::vector<T> choices(bool fixed, T value, std::vector<T> all) {
    return fixed ? std::vector<T>{value} : all;
}

// The image's pixels at the sample, as an image under flip shows them.
std::vector<dvec3> observedAt(const ImageF& levels, const std::vector<glm::ivec2>& samples,
                              Flip flip) {
    std::vector<dvec3> observed;
    observed.reserve(samples.size());
    for (glm::ivec2 p : samples) {
        const glm::ivec2 q = referencePixel(flip, p.x, p.y, levels.width, levels.height);
        const float* v = &levels.rgb[(std::size_t(q.y) * std::size_t(levels.width) + q.x) * 3];
        observed.emplace_back(v[0], v[1], v[2]);
    }
    return observed;
}

// presentedLevel for one setting, by table: the search calls it tens of millions of times,
// and pow is most of its cost. The level of v = clamp(c * brightness) is the number of
// thresholds v reaches (the colour where each level begins); a coarse table gives where
// to start counting. At a threshold itself it may differ from presentedLevel by a level,
// which moves a mean error by nothing the search can see.
class LevelTable {
  public:
    explicit LevelTable(const GlobalSettings& settings) : brightness_(settings.brightness) {
        GlobalSettings plain = settings;
        plain.brightness = 1.0;
        for (int level = 1; level <= 255; ++level) {
            const double centre = plain.quantize == Quantize::Round ? level - 0.5 : level;
            thresholds_[std::size_t(level)] = std::pow(centre / 255.0, plain.gamma);
        }
        thresholds_[0] = -1.0;
        int level = 0;
        for (std::size_t k = 0; k < kCells; ++k) {
            const double v = double(k) / double(kCells);
            while (level < 255 && v >= thresholds_[std::size_t(level) + 1])
                ++level;
            start_[k] = std::uint8_t(level);
        }
    }
    double operator()(double c) const {
        const double v = c * brightness_;
        if (!(v > 0)) return 0.0; // also NaN
        if (v >= 1.0) return 255.0;
        std::size_t level = start_[std::size_t(v * double(kCells))];
        while (level < 255 && v >= thresholds_[level + 1])
            ++level;
        return double(level);
    }

  private:
    static constexpr std::size_t kCells = 4096;
    double brightness_;
    std::array<double, 256> thresholds_{};
    std::array<std::uint8_t, kCells> start_{};
};

// The background solved for (per reference channel, shown) as the options write it: the default
// when every channel is within closeness of it, else in [0, 1] with the fewest decimals that show
// the same.
dvec3 backgroundFor(const GlobalSettings& settings, dvec3 shown, double closeness) {
    const GlobalSettings defaults;
    bool isDefault = true;
    for (int c = 0; c < 3; ++c)
        isDefault =
            isDefault && std::abs(presentedLevel(settings, shown[c]) -
                                  presentedLevel(settings, defaults.background[c])) <= closeness;
    if (isDefault) return defaults.background;
    dvec3 background;
    for (int c = 0; c < 3; ++c)
        background[c] = shortestEquivalent(settings, std::clamp(shown[c], 0.0, 1.0), closeness / 8);
    return background;
}

// One depth and brightness (in s) against the sample, in every channel order.
void tryChannelOrders(const std::vector<RayTerms>& terms, const std::vector<dvec3>& observed,
                      const std::vector<dvec3>& linear, const GlobalSettings& s,
                      const SearchRules& rules, std::vector<Candidate>& out) {
    const std::size_t n = terms.size();
    const std::size_t depth = std::size_t(s.depth);
    const LevelTable presented(s);
    // The background each channel order implies, from the pixels whose colour comes from
    // it in good part (a quarter or more: those whose eye ray misses, and mirrors that show
    // it): solved from colour = own + through * background, the median of them.
    std::vector<dvec3> backgrounds;
    std::vector<double> values;
    for (const std::array<int, 3>& order : rules.orders) {
        dvec3 shown(1.0);
        for (int k = 0; k < 3; ++k) {
            const int c = order[std::size_t(k)];
            values.clear();
            for (std::size_t p = 0; p < n; ++p) {
                const double through = terms[p].throughBackground[depth][c];
                if (through >= 0.25)
                    values.push_back((linear[p][k] / s.brightness - terms[p].own[depth][c]) /
                                     through);
            }
            if (values.size() < 16) continue; // too few to tell: the default
            std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
            shown[c] = values[values.size() / 2];
        }
        backgrounds.push_back(rules.fixed.background ? rules.fixed.values.background
                                                     : backgroundFor(s, shown, rules.closeness));
    }
    std::vector<long> close(rules.orders.size(), 0);
    std::vector<double> errors(rules.orders.size(), 0.0);
    for (std::size_t p = 0; p < n; ++p) {
        const dvec3 own = terms[p].own[depth];
        const dvec3 through = terms[p].throughBackground[depth];
        const bool seesBackground = through != dvec3(0.0);
        dvec3 plain; // the levels when no background is seen (the same in every order)
        if (!seesBackground)
            for (int c = 0; c < 3; ++c)
                plain[c] = presented(own[c]);
        for (std::size_t o = 0; o < rules.orders.size(); ++o) {
            const std::array<int, 3>& order = rules.orders[o];
            bool allClose = true;
            for (int k = 0; k < 3; ++k) {
                const int c = order[std::size_t(k)];
                const double level =
                    seesBackground ? presented(own[c] + through[c] * backgrounds[o][c]) : plain[c];
                const double error = std::abs(level - observed[p][k]);
                errors[o] += error;
                allClose = allClose && error <= rules.closeness;
            }
            close[o] += allClose;
        }
    }
    for (std::size_t o = 0; o < rules.orders.size(); ++o) {
        Candidate candidate{s, 0.0, 0.0};
        candidate.settings.channels = rules.orders[o];
        candidate.settings.background = backgrounds[o];
        candidate.close = double(close[o]) / double(std::max<std::size_t>(n, 1));
        candidate.meanError = errors[o] / double(3 * std::max<std::size_t>(n, 1));
        out.push_back(candidate);
    }
}

// Every setting that the sample's traces serve, for one camera variant and orientation:
// all depths, backgrounds, gammas, quantisations, channel orders and brightnesses.
void tryColourSettings(const std::vector<RayTerms>& terms, const std::vector<dvec3>& observed,
                       GlobalSettings base, const SearchRules& rules, std::vector<Candidate>& out) {
    const FixedSettings& fixed = rules.fixed;
    const std::size_t n = terms.size();
    std::vector<int> depths;
    for (int d = 0; d <= kMaxDepth; ++d)
        depths.push_back(d);
    for (double gamma : choices(fixed.gamma, fixed.values.gamma, {1.0, 2.2}))
        for (Quantize quantize : choices(fixed.quantize, fixed.values.quantize,
                                         {Quantize::Round, Quantize::Truncate})) {
            GlobalSettings post = base;
            post.gamma = gamma;
            post.quantize = quantize;
            post.brightness = 1.0;
            // Each image channel's value as a colour (brightness 1).
            std::vector<dvec3> linear(n);
            for (std::size_t p = 0; p < n; ++p)
                for (int k = 0; k < 3; ++k)
                    linear[p][k] = linearFromLevel(post, observed[p][k]);
            for (int depth : choices(fixed.depth, fixed.values.depth, depths)) {
                // Brightness: the ratio of the image's colour to the reference's where the
                // reference neither clamps nor sees the background (any channel order gives
                // it).
                double brightness = fixed.brightness ? fixed.values.brightness : 1.0;
                if (!fixed.brightness) {
                    double shown = 0, traced = 0;
                    long used = 0;
                    for (std::size_t p = 0; p < n; ++p) {
                        const dvec3 c = terms[p].own[std::size_t(depth)];
                        if (terms[p].throughBackground[std::size_t(depth)] != dvec3(0.0)) continue;
                        // Chosen by the traced colour alone: a choice by the image's
                        // noisy values would bias the ratio.
                        const dvec3& l = linear[p];
                        if (glm::any(glm::lessThan(c, dvec3(0.05))) ||
                            glm::any(glm::greaterThan(c, dvec3(0.8))))
                            continue;
                        shown += l.x + l.y + l.z;
                        traced += c.x + c.y + c.z;
                        ++used;
                    }
                    if (used >= 100 && traced > 0) brightness = shown / traced;
                    brightness = std::round(brightness * 100.0) / 100.0;
                    if (brightness < kLowestBrightness || brightness > kHighestBrightness)
                        brightness = 1.0;
                }
                GlobalSettings settings = post;
                settings.depth = depth;
                settings.brightness = brightness;
                tryChannelOrders(terms, observed, linear, settings, rules, out);
                // The estimate may be noise: the model's brightness is always tried too.
                if (brightness != 1.0 && !fixed.brightness) {
                    settings.brightness = 1.0;
                    tryChannelOrders(terms, observed, linear, settings, rules, out);
                }
            }
        }
}

} // namespace

GlobalSettings givenSettings(const FixedSettings& fixed) {
    GlobalSettings given;
    if (fixed.depth) given.depth = fixed.values.depth;
    if (fixed.background) given.background = fixed.values.background;
    given.fovDegrees = fixed.values.fovDegrees;
    if (fixed.fovAxis) given.fovAxis = fixed.values.fovAxis;
    if (fixed.rays) given.rays = fixed.values.rays;
    if (fixed.flip) given.flip = fixed.values.flip;
    if (fixed.gamma) given.gamma = fixed.values.gamma;
    if (fixed.channels) given.channels = fixed.values.channels;
    if (fixed.brightness) given.brightness = fixed.values.brightness;
    if (fixed.quantize) given.quantize = fixed.values.quantize;
    return given;
}

SearchResult searchGlobalSettings(const Scene& scene, const ImageF& levels,
                                  const FixedSettings& fixed, double closeness, int threads) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<glm::ivec2> samples = searchSamplePixels(levels.width, levels.height);
    SearchResult result;
    result.samplePixels = long(samples.size());

    struct Variant {
        FovAxis axis;
        RayPosition rays;
        Flip flip;
    };
    std::vector<Variant> variants;
    for (FovAxis axis :
         choices(fixed.fovAxis, fixed.values.fovAxis, {FovAxis::Vertical, FovAxis::Horizontal}))
        for (RayPosition rays :
             choices(fixed.rays, fixed.values.rays, {RayPosition::Centre, RayPosition::Corner}))
            for (Flip flip : choices(fixed.flip, fixed.values.flip,
                                     {Flip::None, Flip::Vertical, Flip::Horizontal, Flip::Both}))
                variants.push_back({axis, rays, flip});

    // One trace per camera variant (the orientations share it).
    std::vector<std::vector<RayTerms>> traces;
    std::vector<std::size_t> traceOf(variants.size());
    for (std::size_t v = 0; v < variants.size(); ++v) {
        if (v > 0 && variants[v].axis == variants[v - 1].axis &&
            variants[v].rays == variants[v - 1].rays) {
            traceOf[v] = traceOf[v - 1];
            continue;
        }
        GlobalSettings camera = fixed.values;
        camera.fovAxis = variants[v].axis;
        camera.rays = variants[v].rays;
        ReferenceSettings settings = referenceSettingsFor(camera, levels.width, levels.height);
        settings.depth = fixed.depth ? fixed.values.depth : kMaxDepth;
        traces.push_back(referenceTerms(scene, settings, samples, threads));
        traceOf[v] = traces.size() - 1;
        result.tracedRays += long(samples.size());
    }

    SearchRules rules{
        fixed, closeness, {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    if (fixed.channels) rules.orders = {fixed.values.channels};
    std::vector<std::vector<Candidate>> found(variants.size());
    parallelFor(
        variants.size(),
        [&](std::size_t v) {
            GlobalSettings base = fixed.values;
            base.fovAxis = variants[v].axis;
            base.rays = variants[v].rays;
            base.flip = variants[v].flip;
            tryColourSettings(traces[traceOf[v]], observedAt(levels, samples, variants[v].flip),
                              base, rules, found[v]);
        },
        unsigned(std::max(threads, 0)));

    std::vector<Candidate> all;
    for (const std::vector<Candidate>& some : found)
        all.insert(all.end(), some.begin(), some.end());
    result.candidates = long(all.size());
    double best = 0;
    for (const Candidate& c : all)
        best = std::max(best, c.close);
    const Candidate* chosen = nullptr;
    for (const Candidate& c : all) {
        if (c.close < best - shareSlack(best)) continue;
        const int d = departures(c.settings);
        if (!chosen || d < departures(chosen->settings) ||
            (d == departures(chosen->settings) &&
             (c.close > chosen->close ||
              (c.close == chosen->close && c.meanError < chosen->meanError))))
            chosen = &c;
    }
    result.settings = chosen->settings;
    result.meanError = chosen->meanError;
    result.close = chosen->close;

    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}
