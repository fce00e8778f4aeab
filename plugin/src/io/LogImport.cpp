#include "omnirange/io/LogImport.h"

#include "omnirange/io/AtomicWrite.h"
#include "omnirange/io/CarmenLog.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/OptionsTable.h"
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
			if (!fs::is_regular_file(file)) throw std::invalid_argument("no image file '" + file.string() + "'");
			images.push_back({t, file.string()});
		});
		return images;
	}
	if (!fs::is_directory(dir)) throw std::runtime_error("no image folder '" + dir + "'");
	for (const auto& entry : fs::directory_iterator(dir))
	{
		if (!isImageFileName(entry.path().string()) || entry.is_directory()) continue;
		// Named as an image but a FIFO or a device: it would block the read, and skipping it would lose a frame.
		if (!entry.is_regular_file())
			throw std::runtime_error("'" + entry.path().string() + "' is named as an image but is not a regular file");
		const std::string stem = entry.path().stem().string();
		try
		{
			images.push_back({parseTime(stem), entry.path().string()});
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
	forEachCsvRow(path, "laser log", [&](const std::vector<std::string>& f) {
		if (f.size() < 3) throw std::invalid_argument("expected TIME, then two or more ranges");
		LaserRow row;
		row.time = logTime(f[0]);
		requireTimeAfter(previous, row.time);
		previous = row.time;
		for (std::size_t i = 1; i < f.size(); ++i) row.ranges.push_back(number(f[i], "range " + std::to_string(i - 1)));
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
	forEachCsvRow(path, "odometry log", [&](const std::vector<std::string>& f) {
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

LogImportSummary importLogs(const LogImportOptions& o)
{
	require(o.laser_fov > 0 && o.laser_fov <= 2 * M_PI, "the laser's field of view must be within (0, 360] degrees");
	require(o.laser_max_range > 0, "the laser's max range must be > 0 m");
	requireRawlogOutputAllowed(o.output, kImportProgram, {o.image_list, o.images_dir, o.laser_csv, o.odometry_csv, o.carmen_log}, o.force);
	require(o.carmen_log.empty() || (o.laser_csv.empty() && o.odometry_csv.empty()),
			"a CARMEN log gives the laser and the odometry: not with laser or odometry CSVs too");
	// 1. Read and check everything before writing anything.
	const std::vector<TimedImage> images = listImages(o.images_dir, o.image_list);
	// The output's image folder is replaced at the end: it must hold no input.
	std::vector<std::string> image_files;
	for (const TimedImage& im : images) image_files.push_back(im.file);
	requireRawlogOutputAllowed(o.output, kImportProgram, image_files, o.force);
	std::vector<LaserRow> scans = o.laser_csv.empty() ? std::vector<LaserRow>{} : readLaserCsv(o.laser_csv);
	std::vector<OdometryRow> odometry =
		o.odometry_csv.empty() ? std::vector<OdometryRow>{} : readOdometryCsv(o.odometry_csv);
	double laser_fov = o.laser_fov, laser_max_range = o.laser_max_range;
	mrpt::poses::CPose3D laser_pose = o.laser_pose;
	if (!o.carmen_log.empty())
	{
		CarmenLog log = readCarmenLog(o.carmen_log);
		scans = std::move(log.laser), odometry = std::move(log.odometry);
		laser_fov = log.fov;
		if (log.max_range > 0) laser_max_range = log.max_range;
		// MRPT's scans are centred on the sensor's x axis: turn the pose
		// by where the log's field of view is centred.
		laser_pose = laser_pose + mrpt::poses::CPose3D(0, 0, 0, log.start_angle + 0.5 * log.fov, 0, 0);
	}
	for (const OdometryRow& p : odometry)
		if (!(std::abs(p.x) <= kMaxOdometryCoordinate && std::abs(p.y) <= kMaxOdometryCoordinate &&
			  std::abs(p.phi) <= 1e3))
			throw std::runtime_error("odometry at time " + formatDouble(p.time) + " of '" +
									 (o.carmen_log.empty() ? o.odometry_csv : o.carmen_log) + "' is (" +
									 formatDouble(p.x) + ", " + formatDouble(p.y) + ", " + formatDouble(p.phi) +
									 "): farther than " + formatDouble(kMaxOdometryCoordinate) +
									 " m from its origin, or a heading past 1000 rad");
	LogImportSummary s;
	for (const TimedImage& im : images)
	{
		const cv::Mat m = decodeImageFile(im.file, o.omni_label);
		if (m.empty()) throw std::runtime_error("'" + im.file + "' cannot be read as an image");
		if (s.image_width == 0) s.image_width = m.cols, s.image_height = m.rows;
		if (m.cols != s.image_width || m.rows != s.image_height)
			throw std::runtime_error("'" + im.file + "' is " + std::to_string(m.cols) + "x" + std::to_string(m.rows) +
									 ", the first image " + std::to_string(s.image_width) + "x" +
									 std::to_string(s.image_height) + ": one camera, one size");
	}
	s.rays = scans.empty() ? 0 : static_cast<int>(scans.front().ranges.size());

	// 2. Write the three streams merged in time order; at one time the odometry
	//    first: icp-slam and the guarded matcher take the motion up to an
	//    instant from the odometry before the scans taken at it (as the
	//    simulator writes them), so odometry after them would come a frame late.
	RawlogWriter out(o.output, kImportProgram);
	if (o.force) out.replaceAnyImagesFolder();
	std::size_t i = 0, j = 0, k = 0;
	const auto time = [](auto& v, std::size_t n) { return n < v.size() ? v[n].time : INFINITY; };
	while (i < images.size() || j < scans.size() || k < odometry.size())
	{
		const double ti = time(images, i), tj = time(scans, j), tk = time(odometry, k);
		if (tk <= ti && tk <= tj)
		{
			auto obs = mrpt::obs::CObservationOdometry::Create();
			obs->sensorLabel = o.odometry_label;
			obs->timestamp = mrpt::Clock::fromDouble(tk);
			obs->odometry = mrpt::poses::CPose2D(odometry[k].x, odometry[k].y, odometry[k].phi);
			out.write(*obs);
			++k;
		}
		else if (ti <= tj)
		{
			auto obs = mrpt::obs::CObservationImage::Create();
			obs->sensorLabel = o.omni_label;
			obs->timestamp = mrpt::Clock::fromDouble(ti);
			obs->cameraPose = o.omni_pose;
			obs->cameraParams.ncols = static_cast<uint32_t>(s.image_width);
			obs->cameraParams.nrows = static_cast<uint32_t>(s.image_height);
			char name[64];
			std::snprintf(name, sizeof name, "%s_%06zu", o.omni_label.c_str(), i);
			obs->image = out.externalImageCopy(images[i].file, name + fs::path(images[i].file).extension().string());
			out.write(*obs);
			++i;
		}
		else
		{
			auto obs = mrpt::obs::CObservation2DRangeScan::Create();
			obs->sensorLabel = o.laser_label;
			obs->timestamp = mrpt::Clock::fromDouble(tj);
			obs->sensorPose = laser_pose;
			obs->aperture = static_cast<float>(laser_fov);
			obs->rightToLeft = true;
			obs->maxRange = static_cast<float>(laser_max_range);
			obs->stdError = static_cast<float>(o.laser_std_error);
			obs->resizeScan(scans[j].ranges.size());
			for (std::size_t r = 0; r < scans[j].ranges.size(); ++r)
			{
				const double range = scans[j].ranges[r];
				const bool valid = range > 0 && range < laser_max_range;
				obs->setScanRange(r, static_cast<float>(valid ? range : laser_max_range));
				obs->setScanRangeValidity(r, valid);
			}
			out.write(*obs);
			++j;
		}
	}
	out.commit();
	s.images = images.size(), s.scans = scans.size(), s.odometry = odometry.size();
	s.first_time = std::min({time(images, 0), time(scans, 0), time(odometry, 0)});
	s.last_time = std::max({images.back().time, scans.empty() ? -INFINITY : scans.back().time,
							odometry.empty() ? -INFINITY : odometry.back().time});
	return s;
}

}  // namespace omnirange
