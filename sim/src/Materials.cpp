#include "omnirange_sim/Materials.h"

#include <cmath>
#include <random>

namespace omnirange::sim
{
std::vector<Material> stockMaterials()
{
	// name, RGB, grain, grain contrast, patch, patch contrast, hue jitter
	return {
		{"grass", {{72, 138, 58}}, 0.02, 0.22, 0.9, 0.10, 0.10},
		// The maze's hedges: a green close to the grass's, darker and leafier.
		{"hedge", {{58, 118, 48}}, 0.04, 0.30, 0.6, 0.10, 0.08},
		{"concrete", {{150, 148, 142}}, 0.01, 0.10, 1.5, 0.10, 0.02},
		{"brick", {{150, 72, 55}}, 0.06, 0.18, 0.5, 0.06, 0.04},
		{"metal", {{110, 118, 128}}, 0.02, 0.06, 2.0, 0.05, 0.01},
		{"wood", {{160, 118, 70}}, 0.03, 0.20, 0.4, 0.10, 0.04},
		{"paint_red", {{180, 40, 35}}, 0.02, 0.05, 1.0, 0.05, 0.02},
		{"paint_blue", {{40, 70, 170}}, 0.02, 0.05, 1.0, 0.05, 0.02},
		{"paint_yellow", {{210, 180, 40}}, 0.02, 0.05, 1.0, 0.05, 0.02},
		{"paint_green", {{50, 140, 80}}, 0.02, 0.05, 1.0, 0.05, 0.02},
		{"copper", {{170, 100, 60}}, 0.02, 0.10, 0.5, 0.08, 0.03},
		{"cabinet_grey", {{95, 100, 108}}, 0.02, 0.05, 1.0, 0.04, 0.01},
		{"robot", {{170, 30, 30}}, 0.02, 0.05, 1.0, 0.03, 0.01},
	};
}

NoiseTexture::NoiseTexture(std::uint32_t seed, int size) : n_(size), v_(size * size)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<float> u(0.f, 1.f);
	for (auto& x : v_) x = u(rng);
}

float NoiseTexture::at(double x, double y) const
{
	const double fx = std::floor(x), fy = std::floor(y);
	const float tx = static_cast<float>(x - fx), ty = static_cast<float>(y - fy);
	const int x0 = static_cast<int>(static_cast<long>(fx) & (n_ - 1));
	const int y0 = static_cast<int>(static_cast<long>(fy) & (n_ - 1));
	const int x1 = (x0 + 1) & (n_ - 1), y1 = (y0 + 1) & (n_ - 1);
	const float a = v_[y0 * n_ + x0], b = v_[y0 * n_ + x1];
	const float c = v_[y1 * n_ + x0], d = v_[y1 * n_ + x1];
	// Smoothstep weights hide the grid of the value noise.
	const float sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
	return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

std::array<double, 3> shadeMaterial(
	const Material& m, const NoiseTexture& tex, double a, double b)
{
	const double g = tex.at(a / m.grain, b / m.grain) - 0.5;
	const double p = tex.at(a / m.patch + 13.1, b / m.patch + 7.7) - 0.5;
	const double k = 1.0 + 2.0 * (m.grain_contrast * g + m.patch_contrast * p);
	const double j = 2.0 * m.hue_jitter * (tex.at2(a / m.grain, b / m.grain) - 0.5);
	std::array<double, 3> rgb = m.rgb;
	double kk = k;
	if (m.pattern != "none")
	{
		const double s = m.pattern_size, w = m.pattern_width;
		const double fa = a / s - std::floor(a / s), fb = b / s - std::floor(b / s);
		if (m.pattern == "tiles" && (fa * s < w || fb * s < w)) return {m.pattern_rgb[2], m.pattern_rgb[1], m.pattern_rgb[0]};
		if (m.pattern == "planks")
		{
			if (fb * s < w) return {m.pattern_rgb[2], m.pattern_rgb[1], m.pattern_rgb[0]};
			// Each board its own shade: a texture sample at the board's index.
			kk *= 1.0 + 0.25 * (tex.at(3.7 * std::floor(b / s), 5.3) - 0.5);
		}
	}
	// Returned as B, G, R; the jitter shifts green against red/blue.
	return {rgb[2] * kk * (1 - j), rgb[1] * kk * (1 + j), rgb[0] * kk * (1 - j)};
}

}  // namespace omnirange::sim
