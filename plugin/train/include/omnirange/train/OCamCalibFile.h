#pragma once
// Scaramuzza's OCamCalib toolbox writes its calibration as calib_results.txt:
// the direct polynomial (image radius -> ray), its inverse, the centre (row,
// column), the affine terms c, d, e and the image size, each after a '#'
// comment. This reads it and turns it into the rangefinder's camera keys.

#include <omnirange/core/CameraModel.h>

#include <string>
#include <vector>

namespace omnirange
{
struct OCamCalibFile
{
	std::vector<double> poly;  ///< a0, a1, ...: z of the ray at image radius rho
	std::vector<double> inverse;  ///< the toolbox's inverse polynomial (not needed here; kept)
	double row{0}, column{0};  ///< [px] the centre, from 0
	double c{1}, d{0}, e{0};  ///< the sensor's affine terms
	int height{0}, width{0};  ///< [px]
};

/** Throws std::runtime_error("FILE:LINE: what") on a file that is not
 * OCamCalib's calib_results.txt (a missing value, a wrong count, text). */
OCamCalibFile readOCamCalib(const std::string& path);

/** The rangefinder's camera from it: mirror_model = ocamcalib, ocam_poly,
 * ocam_affine, cx = column, cy = row, the image size; the rest of `start`
 * is kept. */
CameraParams ocamCamera(const OCamCalibFile& f, CameraParams start = {});

}  // namespace omnirange
