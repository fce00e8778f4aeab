#pragma once
// A user's own logs into an MRPT rawlog (observations-only, images external):
// a folder of timestamped omnicam images, a laser log as CSV and, if there
// is one, odometry as CSV. Every observation gets its label, its sensor's
// pose on the robot and its timestamp, and they are written in time order.
// The image files are copied byte for byte. A CARMEN log can stand for the
// laser and odometry CSVs (CarmenLog.h).
//
// Formats (one row per line; '#' starts a comment line; commas between fields):
//   laser CSV:     TIME, r_0, r_1, ..., r_{n-1}     [s], [m]; n the same on every row;
//                  the rays spread evenly over the field of view, right to left
//   odometry CSV:  TIME, x, y, phi                  [s], [m], [m], [rad]
//   image list:    TIME, FILE                       FILE relative to the list's folder;
//                  without a list, each image's file name is its TIME (1700000000.25.jpg)
// TIME is seconds since 1970 (UTC); times increase strictly down each file.

#include <omnirange/config/SensorLabels.h>

#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

namespace omnirange
{
/** The program whose outputs (a rawlog, its images) these are (config/Output.h). */
inline constexpr char kImportProgram[] = "omnirange-import";

struct TimedImage
{
	double time{0};  ///< [s]
	std::string file;
	std::string checked_state;  ///< fileStateOf() the file when it was checked: copied only as it was
};
struct LaserRow
{
	double time{0};  ///< [s]
	std::vector<double> ranges;  ///< [m]
};
/** [m] Odometry farther than this from its origin is refused: a ground
 * robot's log does not span 100 km, and MRPT's maps would be sized by it. */
inline constexpr double kMaxOdometryCoordinate = 1e5;
/** [m/s], [rad/s] Faster than any robot this is for drives or turns: odometry
 * written in millimetres or degrees reads as that (1000 m/s, 10 rad/s). */
inline constexpr double kMaxOdometrySpeed = 10.0;
inline constexpr double kMaxOdometryTurnRate = 2 * 3.141592653589793;
/** [m] The farthest max range a laser log may give (a float in MRPT's scans; past it, a typo). */
inline constexpr double kMaxLaserRange = 1000;

struct OdometryRow
{
	double time{0};  ///< [s]
	double x{0}, y{0}, phi{0};  ///< [m], [m], [rad]
};

/** Times increase strictly down each log: throws std::invalid_argument
 * ("WHAT T is not after the one before it (P): ...") unless time > previous. */
void requireTimeAfter(double previous, double time, const std::string& what = "time");

/** The images of `dir` (jpg, jpeg, png, pgm, ppm, bmp) timed by their names,
 * or the rows of `list_csv` when it is given. Throws std::runtime_error naming
 * the file (and line) on a name or row without a time, times out of order,
 * a missing file, or no image at all. */
std::vector<TimedImage> listImages(const std::string& dir, const std::string& list_csv = "");
/** Throws std::runtime_error("FILE:LINE: ...") on a bad row. */
std::vector<LaserRow> readLaserCsv(const std::string& path);
std::vector<OdometryRow> readOdometryCsv(const std::string& path);

struct LogImportOptions
{
	std::string images_dir, image_list;  ///< the omnicam's images (see listImages)
	std::string laser_csv;  ///< may be empty (no laser)
	std::string odometry_csv;  ///< may be empty (no odometry)
	/** A CARMEN log (CarmenLog.h) instead of the two CSVs: its laser (with
	 * the field of view, first ray's angle and max range it states) and its
	 * odometry. */
	std::string carmen_log;
	std::string output;  ///< the rawlog; its images go to NAME_Images beside it
	std::string omni_label{kOmnicamLabel}, laser_label{kLaserLabel}, odometry_label{kOdometryLabel};
	mrpt::poses::CPose3D omni_pose;  ///< the omnicam on the robot
	mrpt::poses::CPose3D laser_pose;  ///< the laser on the robot
	double laser_fov{3.14159265358979323846};  ///< [rad] from the first ray to the last
	double laser_max_range{19.8};  ///< [m] a range <= 0 or >= this is no return
	double laser_std_error{0.01};  ///< [m]
	/** Replace an output (or NAME_Images) no program of ours wrote (never an input; config/Output.h). */
	bool force{false};
};

struct LogImportSummary
{
	std::size_t images{0}, scans{0}, odometry{0};
	int image_width{0}, image_height{0};
	int rays{0};
	double first_time{0}, last_time{0};  ///< [s]
	/** Images with no laser scan within kDefaultMaxPairingDt: nothing trains
	 * or scores on them (many: clocks apart, by a time zone or a unit). */
	std::size_t images_without_scan{0};
};

/** Checks every input first (each image is decoded once), then writes the
 * rawlog under a temporary name and renames it: a failed import leaves
 * nothing behind. Throws std::runtime_error naming the file and line. */
LogImportSummary importLogs(const LogImportOptions& options);

}  // namespace omnirange
