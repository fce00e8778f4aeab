// The README's library example as a program: one omnicam image to one scan,
// loaded as omnirange-scan loads them (the ini over its base; the colour
// model with the floor's colour from training, so that exposure compensation
// runs). Prints the scan as "ray range status" lines.
//   scan_image INI COLOUR_MODEL IMAGE
#include <omnirange/core/ColourModel.h>
#include <omnirange/core/Rangefinder.h>

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <exception>

int main(int argc, char** argv)
{
	if (argc != 4)
	{
		std::fprintf(stderr, "usage: scan_image INI COLOUR_MODEL IMAGE\n");
		return 2;
	}
	const char *ini = argv[1], *model = argv[2], *image = argv[3];
	try
	{
		// --- README.md: Using the library ---
		const auto params = omnirange::RangefinderParams::loadFromFile(ini, "rangefinder");
		const omnirange::Rangefinder rangefinder(params, omnirange::ColourModel::load(model));
		const cv::Mat bgr = cv::imread(image, cv::IMREAD_COLOR);  // 8-bit BGR, the camera's size
		const omnirange::RangeScan scan = rangefinder.process(bgr);
		const auto obs = rangefinder.toObservation(scan, mrpt::Clock::now());  // a CObservation2DRangeScan
		// --- end ---
		std::printf("# %zu rays, exposure compensation %s\n", scan.rays.size(),
					rangefinder.compensationMissing() ? "missing" : (params.exposure_compensation ? "on" : "off"));
		for (std::size_t i = 0; i < obs->getScanSize(); ++i)
			std::printf("%zu %.6f %d\n", i, obs->getScanRange(i), obs->getScanRangeValidity(i) ? 1 : 0);
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "scan_image: error: %s\n", e.what());
		return 1;
	}
	return 0;
}
