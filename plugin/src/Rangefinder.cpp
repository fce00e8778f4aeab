#include "omnirange/Rangefinder.h"

#include "omnirange/Config.h"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <sstream>

namespace omnirange
{
std::vector<std::string> RangefinderParams::keys()
{
	std::vector<std::string> k = CameraParams::keys();
	for (const char* s :
		 {"scanlines", "base_radius", "min_range", "max_range", "boundary_offset", "N", "K",
		  "threshold", "outlier_filter", "outlier_max_width", "outlier_abs_tol",
		  "outlier_rel_tol", "sensor_label", "std_error"})
		k.emplace_back(s);
	for (const auto& p : sensorPoseKeys()) k.push_back(p);
	return k;
}

void RangefinderParams::loadFromConfig(
	const mrpt::config::CConfigFileBase& c, const std::string& s,
	const std::vector<std::string>& also_allowed)
{
	requireParam(c.sectionExists(s), s, "section not found in the ini file");
	std::vector<std::string> known = keys();
	known.insert(known.end(), also_allowed.begin(), also_allowed.end());
	requireKnownKeys(c, s, known);
	camera.loadFromConfig(c, s);

	scanner.scanlines = c.read_int(s, "scanlines", scanner.scanlines);
	scanner.base_radius = c.read_double(s, "base_radius", scanner.base_radius);
	scanner.min_range = c.read_double(s, "min_range", scanner.min_range);
	scanner.max_range = c.read_double(s, "max_range", scanner.max_range);
	scanner.boundary_offset = c.read_double(s, "boundary_offset", scanner.boundary_offset);
	scanner.filter.N = c.read_int(s, "N", scanner.filter.N);
	scanner.filter.K = c.read_int(s, "K", scanner.filter.K);
	threshold = c.read_double(s, "threshold", threshold);

	outliers.kind = outlierFilterKindFromString(
		c.read_string(s, "outlier_filter", toString(outliers.kind)));
	outliers.max_width = c.read_int(s, "outlier_max_width", outliers.max_width);
	outliers.abs_tol = c.read_double(s, "outlier_abs_tol", outliers.abs_tol);
	outliers.rel_tol = c.read_double(s, "outlier_rel_tol", outliers.rel_tol);

	sensor_label = c.read_string(s, "sensor_label", sensor_label);
	// pose_z defaults to h: the viewpoint is on the camera's axis at that height.
	mrpt::poses::CPose3D def = sensor_pose;
	def.z(camera.h);
	sensor_pose = readSensorPose(c, s, def);
	std_error = c.read_double(s, "std_error", std_error);
	validate();
}

void RangefinderParams::validate() const
{
	camera.validate();
	outliers.validate();
	requireParam(
		threshold >= 0.0 && threshold <= 1.0, "rangefinder",
		"threshold (Theta) must be within [0, 1]");
	requireParam(!sensor_label.empty(), "rangefinder", "sensor_label is empty");
	requireParam(std_error >= 0, "rangefinder", "std_error must be >= 0 m");
	// The scanner checks its own parameters against the camera.
}

std::string RangefinderParams::asIni() const
{
	std::ostringstream o;
	const auto& c = camera;
	o << "image_width = " << c.image_width << "\nimage_height = " << c.image_height
	  << "\ncx = " << c.cx << "\ncy = " << c.cy << "\nR = " << c.R
	  << "\nh = " << c.h << "\nmirror_model = " << toString(c.mirror_model)
	  << "\nalpha = " << c.alpha << "\nforward_azimuth = " << c.forward_azimuth
	  << "\nmirrored = " << (c.mirrored ? "true" : "false")
	  << "\nscanlines = " << scanner.scanlines
	  << "\nbase_radius = " << scanner.base_radius
	  << "\nmin_range = " << scanner.min_range
	  << "\nmax_range = " << scanner.max_range
	  << "\nboundary_offset = " << scanner.boundary_offset << "\nN = " << scanner.filter.N
	  << "\nK = " << scanner.filter.K << "\nthreshold = " << threshold
	  << "\noutlier_filter = " << toString(outliers.kind)
	  << "\noutlier_max_width = " << outliers.max_width
	  << "\noutlier_abs_tol = " << outliers.abs_tol
	  << "\noutlier_rel_tol = " << outliers.rel_tol
	  << "\nsensor_label = " << sensor_label << "\npose_x = " << sensor_pose.x()
	  << "\npose_y = " << sensor_pose.y() << "\npose_z = " << sensor_pose.z()
	  << "\npose_yaw = " << mrpt::RAD2DEG(sensor_pose.yaw())
	  << "\npose_pitch = " << mrpt::RAD2DEG(sensor_pose.pitch())
	  << "\npose_roll = " << mrpt::RAD2DEG(sensor_pose.roll())
	  << "\nstd_error = " << std_error << "\n";
	return o.str();
}

int RangeScan::count(RayStatus s) const
{
	return static_cast<int>(std::count_if(
		rays.begin(), rays.end(), [s](const Ray& r) { return r.status == s; }));
}

Rangefinder::Rangefinder(
	const RangefinderParams& params, const ColourHistogram& histogram)
	: p_((params.validate(), params)),
	  camera_(p_.camera),
	  classifier_(histogram, p_.threshold),
	  scanner_(camera_, p_.scanner)
{
}

RangeScan Rangefinder::process(const cv::Mat& bgr) const
{
	RangeScan out;
	// 1-3. Classify the pixels along each polar scanline, find where the
	//      floor ends with the N/K filters, and convert to metres (eq. (6)).
	out.rays = scanner_.scan(bgr, classifier_);
	// 4. Reject the rays that disagree with both their neighbours.
	out.outliers = rejectOutliers(out.rays, p_.outliers);
	return out;
}

mrpt::obs::CObservation2DRangeScan::Ptr Rangefinder::toObservation(
	const RangeScan& scan, mrpt::Clock::time_point stamp) const
{
	auto obs = mrpt::obs::CObservation2DRangeScan::Create();
	const int S = static_cast<int>(scan.rays.size());
	obs->sensorLabel = p_.sensor_label;
	obs->timestamp = stamp;
	obs->sensorPose = p_.sensor_pose;
	obs->aperture = static_cast<float>(scanAperture(S));
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(p_.scanner.max_range);
	obs->stdError = static_cast<float>(p_.std_error);
	obs->resizeScan(S);
	for (int i = 0; i < S; ++i)
	{
		obs->setScanRange(i, scan.rays[i].range);
		obs->setScanRangeValidity(i, scan.rays[i].status == RayStatus::Hit);
	}
	return obs;
}

}  // namespace omnirange
