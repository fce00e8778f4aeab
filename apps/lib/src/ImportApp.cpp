#include "omnirange_apps/ImportApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/io/ObservationPairer.h>
#include <omnirange/io/RawlogWriter.h>

#include <omnirange/core/Rangefinder.h>
#include <omnirange/config/OptionsTable.h>

#include <cmath>
#include <sstream>

namespace omnirange::app
{
mrpt::poses::CPose3D poseFromText(const std::string& option, const std::string& text)
{
	std::vector<double> v;
	try
	{
		std::istringstream in(text);
		for (std::string value; in >> value;) v.push_back(parseWithin(value, v.size() < 3 ? kMaxMountOffset : kMaxMountAngle));
		if (v.size() != 4 && v.size() != 6) throw std::invalid_argument("not 'x y z yaw_deg' or 'x y z yaw_deg pitch_deg roll_deg'");
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(option + " '" + text + "': " + e.what());
	}
	const double d = M_PI / 180;
	return mrpt::poses::CPose3D(v[0], v[1], v[2], v[3] * d, v.size() == 6 ? v[4] * d : 0, v.size() == 6 ? v[5] * d : 0);
}

ImportApp::Options ImportApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& i = o.import;
	TCLAP::CmdLine cmd("omnirange-import: your images, laser log and odometry -> an MRPT rawlog (docs/users.md)", ' ', "0.1");
	TCLAP::ValueArg<std::string> images("", "images", "folder of omnicam images named by their time in seconds (TIME.jpg)", false, "", "DIR", cmd);
	TCLAP::ValueArg<std::string> list("", "image-list", "CSV of TIME, FILE rows instead of timed names (FILE relative to the CSV)", false, "", "CSV", cmd);
	TCLAP::ValueArg<std::string> laser("", "laser", "laser log: CSV of TIME, r_0, ..., r_{n-1} rows [s, m]", false, "", "CSV", cmd);
	TCLAP::ValueArg<std::string> odometry("", "odometry", "odometry: CSV of TIME, x, y, phi rows [s, m, m, rad]", false, "", "CSV", cmd);
	TCLAP::ValueArg<std::string> carmen("", "carmen", "a CARMEN log (FLASER, RAWLASER1 or ROBOTLASER1, and ODOM) instead of --laser and --odometry", false, "", "LOG", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (images go to NAME_Images beside it)", true, "", "RAWLOG", cmd);
	RangefinderIniArgs ini(cmd, "[rangefinder] pose_* keys giving the omnicam's pose on the robot", false);
	TCLAP::ValueArg<std::string> omni_pose("", "omni-pose", "the omnicam's pose on the robot, 'x y z yaw_deg' [m, deg] (instead of -c)", false, "", "POSE", cmd);
	TCLAP::ValueArg<std::string> laser_pose("", "laser-pose", "the laser's pose on the robot, 'x y z yaw_deg' [m, deg]", false, "0 0 0 0", "POSE", cmd);
	TCLAP::ValueArg<double> fov("", "laser-fov-deg", "the laser's field of view, first ray to last [deg]", false, 180, "DEG", cmd);
	BoundArgs bound(cmd);
	bound.value("", "laser-max-range", "ranges <= 0 or >= this are no return [m]", i.laser_max_range, "M");
	bound.value("", "omni-label", "label of the images", i.omni_label, "LABEL");
	bound.value("", "laser-label", "label of the laser scans", i.laser_label, "LABEL");
	ForceArg force(cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	i.force = force.value();
	i.images_dir = images.getValue(), i.image_list = list.getValue(), i.laser_csv = laser.getValue();
	if (images.isSet() && list.isSet()) throw std::invalid_argument("give the images by --images or by --image-list, not both");
	i.odometry_csv = odometry.getValue(), i.carmen_log = carmen.getValue(), i.output = requiredPath(out);
	i.laser_pose = poseFromText("--laser-pose", laser_pose.getValue());
	i.laser_fov = fov.getValue() * M_PI / 180;
	o.ini = ini.ini.getValue(), o.section = ini.section.getValue();
	if (!omni_pose.getValue().empty())
	{
		if (!o.ini.empty()) throw std::invalid_argument("give the omnicam's pose by -c INI or by --omni-pose, not both");
		i.omni_pose = poseFromText("--omni-pose", omni_pose.getValue());
	}
	if (i.images_dir.empty() && i.image_list.empty())
		throw std::invalid_argument("the images are needed: --images DIR or --image-list CSV");
	o.verbosity = verbosity.level();
	return o;
}

ImportApp::ImportApp(Options o) : mrpt::system::COutputLogger("omnirange-import"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

LogImportSummary ImportApp::run()
{
	// The -c ini (and its bases) is read as surely as the logs: never an output.
	const auto& i = o_.import;
	requireRawlogOutputAllowed(i.output, kImportProgram, {o_.ini, i.images_dir, i.image_list, i.laser_csv, i.odometry_csv, i.carmen_log},
							   i.force);
	if (!o_.ini.empty()) o_.import.omni_pose = loadRangefinderIni(o_.ini, o_.section, *this).sensor_pose;
	const LogImportSummary s = importLogs(o_.import);
	MRPT_LOG_INFO_FMT("%zu images (%dx%d), %zu laser scans (%d rays), %zu odometry readings over %.1f s -> %s",
					  s.images, s.image_width, s.image_height, s.scans, s.rays, s.odometry, s.last_time - s.first_time,
					  o_.import.output.c_str());
	// A few at the ends are a log started or stopped apart; more are clocks apart.
	if (s.scans > 0 && s.images_without_scan * 10 > s.images)
		MRPT_LOG_WARN_FMT("%zu of %zu images have no laser scan within %.1f s, so nothing trains or scores on them: "
						  "are the camera's and the laser's clocks apart (a time zone, another unit)?",
						  s.images_without_scan, s.images, kDefaultMaxPairingDt);
	return s;
}

}  // namespace omnirange::app
