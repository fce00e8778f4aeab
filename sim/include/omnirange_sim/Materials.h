#pragma once
// Surface materials: a base colour modulated by two octaves of value noise
// (fine grain and larger patches), sampled at world coordinates.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace omnirange::sim
{
struct Material
{
	std::string name;
	std::array<double, 3> rgb{{128, 128, 128}};  ///< base colour, 0..255
	double grain{0.03};  ///< [m] size of the fine texture
	double grain_contrast{0.15};  ///< [-] its relative brightness swing
	double patch{0.8};  ///< [m] size of the coarse texture
	double patch_contrast{0.08};  ///< [-] its relative brightness swing
	double hue_jitter{0.05};  ///< [-] per-channel swing of the fine texture
	/** A regular pattern over the texture: none; tiles (square tiles of
	 * pattern_size with grout lines pattern_width wide in pattern_rgb);
	 * planks (boards pattern_size wide along the first coordinate, seams of
	 * pattern_width, each board a little lighter or darker). */
	std::string pattern{"none"};
	double pattern_size{0.4};  ///< [m] tile side or board width
	double pattern_width{0.006};  ///< [m] grout or seam width
	std::array<double, 3> pattern_rgb{{90, 90, 90}};  ///< grout or seam colour, 0..255
};

/** The materials every world has: grass, hedge, concrete, brick, metal, wood,
 * paint_* and the robot's. */
std::vector<Material> stockMaterials();

/** Tileable value noise in [0, 1], deterministic for a seed. */
class NoiseTexture
{
   public:
	explicit NoiseTexture(std::uint32_t seed, int size = 256);
	/** Bilinear sample at (x, y) in texture cells. */
	float at(double x, double y) const;
	/** Second, independent channel (for colour variation). */
	float at2(double x, double y) const { return at(x + 97.31, y + 41.77); }

   private:
	int n_;
	std::vector<float> v_;
};

/** Colour (B, G, R as doubles, 0..255, before lighting) of `m` at surface
 * coordinates (a, b) [m]. */
std::array<double, 3> shadeMaterial(
	const Material& m, const NoiseTexture& tex, double a, double b);

}  // namespace omnirange::sim
