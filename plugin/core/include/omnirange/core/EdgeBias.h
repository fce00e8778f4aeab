#pragma once
// A learned correction of where the floor ends, by the contrast at the hit.
// The floor darkens towards what stands on it (the contact shadow, the
// shadow the obstacle casts, blur from its lower edge), and a colour model
// trained on the open floor stops calling it free before the obstacle's
// foot: the hit is short by the width of that darkened band. How short
// depends on what the hit looks like, not on the floor's colour: a hit
// pixel much darker or brighter than the floor just before it is the
// obstacle's own edge, one little darker is mostly the darkened floor, and
// a look-alike obstacle gives the same small contrast with its foot further
// on. So the contrast is cut into bins and each bin adds its own range,
// learned against the laser (EdgeBiasLearning.h; docs/method.md).

#include <cstdint>
#include <limits>
#include <vector>

namespace omnirange
{
/** Contrast bins: natural log of the brightness ratio, from kEdgeContrastFrom
 * in steps of kEdgeContrastStep, kEdgeContrastBins of them. A hit darker
 * than e^-0.5 (61 %) of the floor before it is the obstacle's own face, not
 * floor in its shadow, and gets no bias: there the laser and the floor's end
 * part where a face is not vertical (docs/method.md). */
constexpr double kEdgeContrastFrom = -0.5;
constexpr double kEdgeContrastStep = 0.05;
constexpr int kEdgeContrastBins = 20;
/** The floor compared with the hit: pixels kEdgeFloorFrom to kEdgeFloorTo before it. */
constexpr int kEdgeFloorFrom = 8, kEdgeFloorTo = 4;
/** [m] the largest correction a bin may add or take away. */
constexpr double kMaxEdgeBias = 0.5;

/** The hit's contrast: the natural log of the brightness (B + G + R) of
 * scanline pixel `hit` over the mean brightness of pixels hit - 8 to hit - 4
 * (both with a small offset for the dark's noise); NaN when hit < 8. */
float edgeContrast(const std::uint8_t* bgr, const std::int32_t* pixels, int hit);

/** The bin of a contrast, or -1 when it is NaN or outside the bins. */
int edgeContrastBin(double contrast);

/** [m] what `bias` (one value per bin, from the first; shorter lists leave
 * the rest at 0) adds to a hit of this contrast: each value holds at its
 * bin's centre, linear between centres (the first and last hold to their
 * bins' outer edges); 0 outside the bins. */
double edgeBiasAt(const std::vector<double>& bias, double contrast);

}  // namespace omnirange
