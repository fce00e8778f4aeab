#include "omnirange/io/LogImport.h"

#include <omnirange/config/Output.h>
#include "omnirange/io/CarmenLog.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/ObservationPairer.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/io/RawlogWriter.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>

namespace fs = std::filesystem;

namespace omnirange
{
namespace
{
/** Calls `row(fields)` for every row of a CSV (fields split at commas,
 * trimmed); errors name the file and line (forEachDataLine). */
void forEachCsvRow(const std::string& path, const std::string& what,
				   const std::function<void(const std::vector<std::string>&)>& row)
{
	std::vector<std::string> fields;
	const int rows = forEachDataLine(path, what, [&](int, const std::string& t) {
		fields.clear();
		std::size_t start = 0;
		for (std::size_t comma; (comma = t.find(',', start)) != std::string::npos; start = comma + 1)
			fields.push_back(trimmed(t.substr(start, comma - start)));
		fields.push_back(trimmed(t.substr(start)));
		row(fields);
	});
	if (rows == 0) throw std::runtime_error("the " + what + " '" + path + "' has no rows");
}

double logTime(const std::string& field)
{
	try
	{
		return parseTime(field);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument("time '" + field + "': " + e.what());
	}
}

double number(const std::string& field, const std::string& name)
{
	try
	{
		return parseDouble(field);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(name + " '" + field + "': " + e.what());
	}
}

/** A row the same as the one before it (a logger that wrote a line twice) is said as such, not as time gone back. */
void requireNotRepeated(std::vector<std::string>& before, const std::vector<std::string>& row)
{
	if (row == before) throw std::invalid_argument("the same row as the one before it (logged twice?): remove one of them");
	before = row;
}
}  // namespace

void requireTimeAfter(double previous, double time, const std::string& what)
{
	if (!(time > previous))
		throw std::invalid_argument(what + " " + formatDouble(time) + " is not after the one before it (" +
									formatDouble(previous) + "): rows must be in time order");
}

std::vector<TimedImage> listImages(const std::string& dir, const std::string& list_csv)
{
	std::vector<TimedImage> images;
	if (!list_csv.empty())
	{
		const fs::path base = fs::path(list_csv).parent_path();
		double previous = -INFINITY;
		forEachCsvRow(list_csv, "image list", [&](const std::vector<std::string>& f) {
			if (f.size() != 2) throw std::invalid_argument("expected TIME, FILE");
			const double t = logTime(f[0]);
			requireTimeAfter(previous, t);
			previous = t;
			const fs::path file = base / f[1];
			std::error_code ec;
			if (!fs::is_regular_file(file, ec))
				throw std::invalid_argument(ec == std::errc::too_many_symbolic_link_levels
												? "'" + file.string() + "' is a link that leads back to itself"
											: fs::exists(fs::symlink_status(file, ec)) ? "'" + file.string() + "' is not a regular file"
																					   : "no image file '" + file.string() + "'");
			images.push_back({t, file.string(), ""});
		});
		return images;
	}
	if (!fs::is_directory(dir)) throw std::runtime_error("no image folder '" + dir + "'");
	for (const auto& entry : fs::directory_iterator(dir))
	{
		if (!isImageFileName(entry.path().string())) continue;
		// Named as an image but a folder, a FIFO or a device: skipping it would lose a frame (and a FIFO would block).
		std::error_code ec;
		if (!entry.is_regular_file(ec))
			throw std::runtime_error("'" + entry.path().string() + "' is named as an image but is " +
									 (ec == std::errc::too_many_symbolic_link_levels
										  ? "a link that leads back to itself, or one of more than 40 in a row"
										  : "not a regular file"));
		const std::string stem = entry.path().stem().string();
		try
		{
			images.push_back({parseTime(stem), entry.path().string(), ""});
		}
		catch (const std::invalid_argument&)
		{
			throw std::runtime_error("'" + entry.path().string() +
									 "': the file name is not a time in decimal seconds below 1e11 (name images TIME.jpg, or "
									 "give an image list)");
		}
	}
	if (images.empty()) throw std::runtime_error("no image (jpg, png, pgm, ppm, bmp) in '" + dir + "'");
	std::sort(images.begin(), images.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
	for (std::size_t i = 1; i < images.size(); ++i)
		if (images[i].time == images[i - 1].time)
			throw std::runtime_error("'" + images[i - 1].file + "' and '" + images[i].file + "' have the same time");
	return images;
}

std::vector<LaserRow> readLaserCsv(const std::string& path)
{
	std::vector<LaserRow> rows;
	double previous = -INFINITY;
	std::vector<std::string> before;
	forEachCsvRow(path, "laser log", [&](const std::vector<std::string>& f) {
		requireNotRepeated(before, f);
		if (f.size() < 3) throw std::invalid_argument("expected TIME, then two or more ranges");
		LaserRow row;
		row.time = logTime(f[0]);
		requireTimeAfter(previous, row.time);
		previous = row.time;
		for (std::size_t i = 1; i < f.size(); ++i)
		{
			// "2,050" split at its comma: no one writes a range "050", but a decimal comma leaves one.
			if (f[i].size() > 1 && f[i][0] == '0' && f[i].find_first_not_of("0123456789") == std::string::npos)
				throw std::invalid_argument("range " + std::to_string(i - 1) + " '" + f[i] +
											"': a whole number with a leading zero, as a decimal comma leaves (write "
											"2.05, not 2,05: fields are split at commas)");
			row.ranges.push_back(number(f[i], "range " + std::to_string(i - 1)));
		}
		if (!rows.empty() && row.ranges.size() != rows.front().ranges.size())
			throw std::invalid_argument(std::to_string(row.ranges.size()) + " ranges, but the first row has " +
										std::to_string(rows.front().ranges.size()));
		rows.push_back(std::move(row));
	});
	return rows;
}

std::vector<OdometryRow> readOdometryCsv(const std::string& path)
{
	std::vector<OdometryRow> rows;
	double previous = -INFINITY;
	std::vector<std::string> before;
	forEachCsvRow(path, "odometry log", [&](const std::vector<std::string>& f) {
		requireNotRepeated(before, f);
		if (f.size() != 4) throw std::invalid_argument("expected TIME, x, y, phi");
		OdometryRow row;
		row.time = logTime(f[0]);
		requireTimeAfter(previous, row.time);
		previous = row.time;
		row.x = number(f[1], "x"), row.y = number(f[2], "y"), row.phi = number(f[3], "phi");
		rows.push_back(row);
	});
	return rows;
}

namespace
{
/** What the user's logs hold, read and checked, ready to be written. */
struct UserLogs
{
	std::vector<TimedImage> images;
	std::vector<LaserRow> scans;
	std::vector<OdometryRow> odometry;
	double laser_fov{0}, laser_max_range{0};
	mrpt::poses::CPose3D laser_pose;
	int image_width{0}, image_height{0};
};

/** The time of `rows[n]`, or +infinity past their end. */
template <class Rows>
double timeOf(const Rows& rows, std::size_t n)
{
	return n < rows.size() ? rows[n].time : INFINITY;
}

/** A log whose times share nothing with the images' is of another run, or
 * written in another unit: nothing in it could be paired. */
template <class Rows>
void requireSharedTime(const std::vector<TimedImage>& images, const Rows& rows, const std::string& file)
{
	if (rows.empty() || (rows.front().time <= images.back().time && images.front().time <= rows.back().time)) return;
	throw std::runtime_error("'" + file + "' runs from " + formatDouble(rows.front().time) + " to " +
							 formatDouble(rows.back().time) + " s, the images from " + formatDouble(images.front().time) +
							 " to " + formatDouble(images.back().time) + " s: no time in common (another run, or another unit?)");
}

UserLogs readUserLogs(const LogImportOptions& o)
{
	UserLogs u;
	u.images = listImages(o.images_dir, o.image_list);
	// The output's image folder is replaced at the end: it must hold no input.
	std::vector<std::string> image_files;
	for (const TimedImage& im : u.images) image_files.push_back(im.file);
	requireRawlogOutputAllowed(o.output, kImportProgram, image_files, o.force);
	if (!o.laser_csv.empty()) u.scans = readLaserCsv(o.laser_csv);
	if (!o.odometry_csv.empty()) u.odometry = readOdometryCsv(o.odometry_csv);
	u.laser_fov = o.laser_fov, u.laser_max_range = o.laser_max_range, u.laser_pose = o.laser_pose;
	if (!o.carmen_log.empty())
	{
		CarmenLog log = readCarmenLog(o.carmen_log);
		u.scans = std::move(log.laser), u.odometry = std::move(log.odometry);
		u.laser_fov = log.fov;
		if (log.max_range > 0) u.laser_max_range = log.max_range;
		// MRPT's scans are centred on the sensor's x axis: turn the pose
		// by where the log's field of view is centred.
		u.laser_pose = u.laser_pose + mrpt::poses::CPose3D(0, 0, 0, log.start_angle + 0.5 * log.fov, 0, 0);
	}
	require(u.laser_max_range <= kMaxLaserRange,
			"the laser's max range, " + formatDouble(u.laser_max_range) + " m, is past " + formatDouble(kMaxLaserRange) + " m");
	const std::string laser_file = o.carmen_log.empty() ? o.laser_csv : o.carmen_log;
	const std::string odometry_file = o.carmen_log.empty() ? o.odometry_csv : o.carmen_log;
	// A laser that never returns teaches nothing: ranges in millimetres, or the wrong max range.
	const bool any_return = std::any_of(u.scans.begin(), u.scans.end(), [&](const LaserRow& row) {
		return std::any_of(row.ranges.begin(), row.ranges.end(), [&](double r) { return r > 0 && r < u.laser_max_range; });
	});
	if (!u.scans.empty() && !any_return)
		throw std::runtime_error("no range of '" + laser_file + "' lies within (0, " + formatDouble(u.laser_max_range) +
								 ") m, the laser's max range: ranges in millimetres, or another max range?");
	// No laser measures in whole metres: "2,1" (a decimal comma) read as the two rays 2 and 1 leaves only such.
	const bool all_whole = std::all_of(u.scans.begin(), u.scans.end(), [](const LaserRow& row) {
		return std::all_of(row.ranges.begin(), row.ranges.end(), [](double r) { return r == std::floor(r); });
	});
	if (!u.scans.empty() && all_whole)
		throw std::runtime_error("every range of '" + laser_file + "' is a whole number of metres: written with " +
								 "decimal commas (2,1 is read as the two rays 2 and 1), or in another unit?");
	requireSharedTime(u.images, u.scans, laser_file), requireSharedTime(u.images, u.odometry, odometry_file);
	for (const OdometryRow& p : u.odometry)
		if (!(std::abs(p.x) <= kMaxOdometryCoordinate && std::abs(p.y) <= kMaxOdometryCoordinate &&
			  std::abs(p.phi) <= 1e3))
			throw std::runtime_error("odometry at time " + formatDouble(p.time) + " of '" + odometry_file + "' is (" +
									 formatDouble(p.x) + ", " + formatDouble(p.y) + ", " + formatDouble(p.phi) +
									 "): farther than " + formatDouble(kMaxOdometryCoordinate) +
									 " m from its origin, or a heading past 1000 rad");
	// Over at least 50 ms: a clock's jitter between two close rows is no speed.
	for (std::size_t i = 1, from = 0; i < u.odometry.size(); ++i)
	{
		const OdometryRow &a = u.odometry[from], &b = u.odometry[i];
		const double dt = b.time - a.time;
		if (dt < 0) from = i;
		if (!(dt >= 0.05)) continue;
		from = i;
		const double speed = std::hypot(b.x - a.x, b.y - a.y) / dt;
		const double turn = std::abs(std::remainder(b.phi - a.phi, 2 * M_PI)) / dt;  // a heading may wrap
		if (speed > kMaxOdometrySpeed || turn > kMaxOdometryTurnRate)
			throw std::runtime_error("odometry of '" + odometry_file + "' from time " + formatDouble(a.time) + " to " +
									 formatDouble(b.time) + " moves " + formatDouble(std::round(speed * 100) / 100) +
									 " m/s and turns " + formatDouble(std::round(turn * 100) / 100) +
									 " rad/s, past any robot's (" + formatDouble(kMaxOdometrySpeed) + " m/s, " +
									 formatDouble(std::round(kMaxOdometryTurnRate * 100) / 100) +
									 " rad/s): x and y in millimetres, the heading in degrees, or a jump (a reset)?");
	}
	for (TimedImage& im : u.images)
	{
		im.checked_state = fileStateOf(im.file);  // before it is read: a change after is found when it is copied
		const cv::Mat m = decodeImageFile(im.file, o.omni_label);
		if (u.image_width == 0) u.image_width = m.cols, u.image_height = m.rows;
		if (m.cols != u.image_width || m.rows != u.image_height)
			throw std::runtime_error("'" + im.file + "' is " + std::to_string(m.cols) + "x" + std::to_string(m.rows) +
									 ", the first image " + std::to_string(u.image_width) + "x" +
									 std::to_string(u.image_height) + ": one camera, one size");
	}
	return u;
}

void writeOdometry(RawlogWriter& out, const LogImportOptions& o, const OdometryRow& row)
{
	auto obs = mrpt::obs::CObservationOdometry::Create();
	obs->sensorLabel = o.odometry_label;
	obs->timestamp = mrpt::Clock::fromDouble(row.time);
	obs->odometry = mrpt::poses::CPose2D(row.x, row.y, row.phi);
	out.write(*obs);
}

void writeImage(RawlogWriter& out, const LogImportOptions& o, const UserLogs& u, std::size_t i)
{
	auto obs = mrpt::obs::CObservationImage::Create();
	obs->sensorLabel = o.omni_label;
	obs->timestamp = mrpt::Clock::fromDouble(u.images[i].time);
	obs->cameraPose = o.omni_pose;
	obs->cameraParams.ncols = static_cast<uint32_t>(u.image_width);
	obs->cameraParams.nrows = static_cast<uint32_t>(u.image_height);
	char name[64];
	std::snprintf(name, sizeof name, "%s_%06zu", o.omni_label.c_str(), i);
	obs->image = out.externalImageCopy(u.images[i].file, name + fs::path(u.images[i].file).extension().string(),
									   u.images[i].checked_state);
	out.write(*obs);
}

void writeScan(RawlogWriter& out, const LogImportOptions& o, const UserLogs& u, const LaserRow& row)
{
	auto obs = mrpt::obs::CObservation2DRangeScan::Create();
	obs->sensorLabel = o.laser_label;
	obs->timestamp = mrpt::Clock::fromDouble(row.time);
	obs->sensorPose = u.laser_pose;
	obs->aperture = static_cast<float>(u.laser_fov);
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(u.laser_max_range);
	obs->stdError = static_cast<float>(o.laser_std_error);
	obs->resizeScan(row.ranges.size());
	for (std::size_t r = 0; r < row.ranges.size(); ++r)
	{
		const double range = row.ranges[r];
		const bool valid = range > 0 && range < u.laser_max_range;
		obs->setScanRange(r, static_cast<float>(valid ? range : u.laser_max_range));
		obs->setScanRangeValidity(r, valid);
	}
	out.write(*obs);
}
}  // namespace

LogImportSummary importLogs(const LogImportOptions& o)
{
	require(o.laser_fov > 0 && o.laser_fov <= 2 * M_PI, "the laser's field of view must be within (0, 360] degrees");
	require(o.laser_max_range > 0, "the laser's max range must be > 0 m");
	requireRawlogOutputAllowed(o.output, kImportProgram, {o.image_list, o.images_dir, o.laser_csv, o.odometry_csv, o.carmen_log}, o.force);
	require(o.carmen_log.empty() || (o.laser_csv.empty() && o.odometry_csv.empty()),
			"a CARMEN log gives the laser and the odometry: not with laser or odometry CSVs too");
	// 1. Read and check everything before writing anything.
	const UserLogs u = readUserLogs(o);

	// 2. Write the three streams merged in time order; at one time the odometry
	//    first: icp-slam and the guarded matcher take the motion up to an
	//    instant from the odometry before the scans taken at it (as the
	//    simulator writes them), so odometry after them would come a frame late.
	RawlogWriter out(o.output, kImportProgram, o.force);
	std::size_t i = 0, j = 0, k = 0;
	while (i < u.images.size() || j < u.scans.size() || k < u.odometry.size())
	{
		const double ti = timeOf(u.images, i), tj = timeOf(u.scans, j), tk = timeOf(u.odometry, k);
		if (tk <= ti && tk <= tj) writeOdometry(out, o, u.odometry[k++]);
		else if (ti <= tj) writeImage(out, o, u, i++);
		else writeScan(out, o, u, u.scans[j++]);
	}
	out.commit();
	LogImportSummary s;
	s.image_width = u.image_width, s.image_height = u.image_height;
	s.rays = u.scans.empty() ? 0 : static_cast<int>(u.scans.front().ranges.size());
	s.images = u.images.size(), s.scans = u.scans.size(), s.odometry = u.odometry.size();
	s.first_time = std::min({timeOf(u.images, 0), timeOf(u.scans, 0), timeOf(u.odometry, 0)});
	s.last_time = std::max({u.images.back().time, u.scans.empty() ? -INFINITY : u.scans.back().time,
							u.odometry.empty() ? -INFINITY : u.odometry.back().time});
	if (!u.scans.empty())
		for (const TimedImage& im : u.images)
		{
			const auto after = std::lower_bound(u.scans.begin(), u.scans.end(), im.time,
												[](const LaserRow& row, double t) { return row.time < t; });
			const bool near = (after != u.scans.end() && after->time - im.time <= kDefaultMaxPairingDt) ||
							  (after != u.scans.begin() && im.time - std::prev(after)->time <= kDefaultMaxPairingDt);
			if (!near) ++s.images_without_scan;
		}
	return s;
}

}  // namespace omnirange
