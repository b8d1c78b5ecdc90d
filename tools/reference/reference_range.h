// What the reference allows a pixel to be: the range of values the CPU reference gives
// over the pixel-centre ray and eight rays moved a tiny sub-pixel distance from it. A GPU
// pixel is wrong when some channel lies outside that range by more than a tolerance.
//
// Why a range and not one value: where the reference itself changes under a tiny
// perturbation of the ray (a silhouette, a shadow edge, their reflections: knife-edge
// pixels), fp32 and fp64 may legitimately send the ray to different sides; the range then
// spans both sides and either answer is accepted. Where the reference does not change
// (inside a flat face, a sphere's interior, a lit ground) the range is one value, so a
// crack showing the background through a closed mesh, shadow acne, or a missed sphere is
// never excused: the wrong value lies outside whatever the nearby rays see.
#pragma once

#include "base/image_io.h"
#include "reference/reference_renderer.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

struct PerturbationSettings {
    // The neighbours sit this many pixels from the centre (axis and diagonal directions)...
    double minimumPixels = 0.01;
    // ...or further where a pixel is so narrow that binary32 cannot place geometry that
    // finely: this angle (2^-21 rad, a few float ulps of a unit direction) as seen from
    // the eye. It only matters for very narrow fields of view (far_sphere: 1.4 px at
    // distance/radius 1e5, where a float has 128 steps across the sphere's radius).
    double minimumRadians = 4.76837158203125e-7;
};

// The reference's centre image, with the per-pixel range computed on demand (only pixels
// a compared image disagrees with need it). Not thread-safe.
class ReferenceRange {
  public:
    ReferenceRange(const Scene& scene, const ReferenceSettings& settings,
                   PerturbationSettings perturbation = {});
    const Image8& centre() const { return centre_; }
    double perturbationPixels() const { return delta_; }
    // Smallest and largest byte of channel c (0..2) over the centre and its neighbours.
    std::uint8_t low(int x, int y, int c);
    std::uint8_t high(int x, int y, int c);

  private:
    void ensure(int x, int y);
    const Scene& scene_;
    ReferenceSettings settings_;
    double delta_;
    Image8 centre_;
    std::vector<std::uint8_t> low_, high_; // RGB per pixel
    std::vector<bool> known_;
};

struct StabilityCount {
    long pixels = 0;
    long differing = 0;     // some channel differs from the centre reference by more than tolerance
    long wrong = 0;         // ... and lies outside the range by more than tolerance
    double failureRate = 0; // wrong / pixels
    int worstX = -1, worstY = -1, worstExcess = 0; // the pixel furthest outside its range
};

// Throws std::invalid_argument when the image's size is not the reference's.
StabilityCount countWrongPixels(const Image8& image, ReferenceRange& range, int tolerance);

// A dim grey copy of image with wrong pixels in red and excused (knife-edge) ones in yellow.
Image8 wrongPixelImage(const Image8& image, ReferenceRange& range, int tolerance);
