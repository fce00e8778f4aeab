#include "omnirange_sim/CameraEffects.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace omnirange::sim
{
void applyOptics(cv::Mat& bgr, const CameraEffectsParams& p, double cx, double cy, double rim_rho)
{
	if (p.vignetting > 0)
	{
		cv::Mat f;
		bgr.convertTo(f, CV_32FC3);
		for (int v = 0; v < f.rows; ++v)
		{
			auto* px = f.ptr<cv::Vec3f>(v);
			for (int u = 0; u < f.cols; ++u)
			{
				const double r2 = (std::pow(u - cx, 2) + std::pow(v - cy, 2)) / (rim_rho * rim_rho);
				px[u] *= static_cast<float>(std::max(0.0, 1.0 - p.vignetting * r2));
			}
		}
		f.convertTo(bgr, CV_8UC3);
	}
	if (p.blur_sigma > 0) cv::GaussianBlur(bgr, bgr, cv::Size(), p.blur_sigma);
}

void applyExposure(cv::Mat& bgr, const CameraEffectsParams& p, int frame)
{
	if (p.exposure_drift <= 0 && p.white_balance_drift <= 0) return;
	const double phase = std::sin(2 * 3.14159265358979323846 * frame / p.drift_period);
	const double gain = 1.0 + p.exposure_drift * phase;
	const double wb = p.white_balance_drift * phase;
	// B, G, R gains: warmer light raises red against blue.
	cv::multiply(bgr, cv::Scalar(gain * (1 - wb), gain, gain * (1 + wb)), bgr);
}

void applyBayer(cv::Mat& bgr)
{
	// An RGGB sensor: R at (even row, even col), B at (odd, odd), G elsewhere.
	cv::Mat raw(bgr.size(), CV_8UC1);
	for (int v = 0; v < bgr.rows; ++v)
	{
		const auto* px = bgr.ptr<cv::Vec3b>(v);
		auto* r = raw.ptr<std::uint8_t>(v);
		for (int u = 0; u < bgr.cols; ++u)
			r[u] = (v % 2 == 0 && u % 2 == 0) ? px[u][2] : (v % 2 == 1 && u % 2 == 1) ? px[u][0] : px[u][1];
	}
	// OpenCV names Bayer patterns by the second row's first two pixels: RGGB is "BG".
	cv::cvtColor(raw, bgr, cv::COLOR_BayerBG2BGR);
}

}  // namespace omnirange::sim
