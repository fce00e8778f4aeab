#include "omnirange/io/CarmenLog.h"

#include "omnirange/config/OptionsTable.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace omnirange
{
namespace
{
/** The blank-separated fields of a line, read one by one. */
class Fields
{
   public:
	explicit Fields(const std::string& line)
	{
		std::istringstream in(line);
		for (std::string f; in >> f;) f_.push_back(f);
		if (f_.empty()) throw std::invalid_argument("a line of blanks only");
	}
	std::size_t left() const { return f_.size() - next_; }
	void need(std::size_t n, const std::string& what) const
	{
		if (left() < n)
			throw std::invalid_argument(f_.front() + ": " + std::to_string(f_.size() - 1) + " fields; " + what);
	}
	/** Exactly `n` more fields: a record with more is read a field off (a count one short of its ranges). */
	void needExactly(std::size_t n, const std::string& what) const
	{
		need(n, what);
		if (left() > n)
			throw std::invalid_argument(f_.front() + ": " + std::to_string(f_.size() - 1) + " fields, too many: " + what + " (is a count short?)");
	}
	std::string word() { return take("a word"); }
	double number(const std::string& name) { return parsed(name, parseDouble); }
	/** [s] A timestamp: decimal seconds within MRPT's clock (parseTime()). */
	double time(const std::string& name) { return parsed(name, parseTime); }
	/** A count of fields that must follow it. */
	int count(const std::string& name)
	{
		const double v = number(name);
		if (!(v >= 0 && v <= static_cast<double>(left()) && v == std::floor(v)))
			throw std::invalid_argument(f_.front() + ": " + name + " " + formatDouble(v) +
										" is not a count of the fields that follow (" + std::to_string(left()) + ")");
		return static_cast<int>(v);
	}
	void skip(std::size_t n, const std::string& what)
	{
		need(n, "expected " + what);
		next_ += n;
	}

   private:
	/** The next field through `parse`, its error naming the record and the field. */
	double parsed(const std::string& name, double (*parse)(const std::string&))
	{
		const std::string& f = take(name);
		try
		{
			return parse(f);
		}
		catch (const std::invalid_argument& e)
		{
			throw std::invalid_argument(f_.front() + ": " + name + " '" + f + "': " + e.what());
		}
	}
	const std::string& take(const std::string& name)
	{
		if (next_ >= f_.size()) throw std::invalid_argument(f_.front() + ": " + name + " is missing");
		return f_[next_++];
	}

	std::vector<std::string> f_;
	std::size_t next_{0};
};

/** A CARMEN log read message by message. */
struct CarmenReader
{
	CarmenLog log;
	std::vector<OdometryRow> laser_poses;  // the odometry when the log has no ODOM message

	/** The first laser message sets the laser; the others must agree with it. */
	void addScan(const std::string& kind, double start, double fov, double max_range, LaserRow row)
	{
		if (row.ranges.size() < 2) throw std::invalid_argument(kind + ": a scan needs two or more ranges");
		if (log.laser.empty())
			log.laser_message = kind, log.start_angle = start, log.fov = fov, log.max_range = max_range;
		else
		{
			if (kind != log.laser_message)
				throw std::invalid_argument(kind + " after " + log.laser_message + ": one laser message kind per log");
			if (start != log.start_angle || fov != log.fov || max_range != log.max_range)
				throw std::invalid_argument(kind + ": the laser's start angle, field of view or max range changed");
			if (row.ranges.size() != log.laser.front().ranges.size())
				throw std::invalid_argument(kind + ": " + std::to_string(row.ranges.size()) +
											" ranges, but the first scan has " +
											std::to_string(log.laser.front().ranges.size()));
			requireTimeAfter(log.laser.back().time, row.time, "laser time");
		}
		log.laser.push_back(std::move(row));
	}

	void flaser(Fields& f)
	{
		f.need(1, "expected the number of readings");
		const int n = f.count("num_readings");
		f.needExactly(n + 9, "expected " + std::to_string(n) + " ranges, two poses and three time fields");
		LaserRow row;
		for (int i = 0; i < n; ++i) row.ranges.push_back(f.number("range " + std::to_string(i)));
		f.skip(3, "the laser's pose");
		OdometryRow pose;
		pose.x = f.number("odom_x"), pose.y = f.number("odom_y"), pose.phi = f.number("odom_theta");
		row.time = pose.time = f.time("ipc_timestamp");
		addScan("FLASER", log.start_angle, log.fov, 0, std::move(row));
		laser_poses.push_back(pose);
	}

	/** RAWLASER1, or ROBOTLASER1 (which adds the robot's pose). */
	void rawLaser(const std::string& kind, Fields& f)
	{
		f.need(8, "expected type, start_angle, field_of_view, resolution, max_range, accuracy, mode, n");
		f.skip(1, "laser_type");
		const double start = f.number("start_angle"), fov = f.number("field_of_view");
		f.skip(1, "angular_resolution");
		const double max_range = f.number("maximum_range");
		f.skip(2, "accuracy and remission_mode");
		const int n = f.count("num_readings");
		f.need(n + 1, "expected " + std::to_string(n) + " ranges and the number of remissions");
		LaserRow row;
		for (int i = 0; i < n; ++i) row.ranges.push_back(f.number("range " + std::to_string(i)));
		const int m = f.count("num_remissions");
		f.skip(m, std::to_string(m) + " remissions");
		OdometryRow pose;
		if (kind == "ROBOTLASER1")
		{
			f.need(11, "expected the laser's and the robot's poses, five motion fields and the times");
			f.skip(3, "the laser's pose");
			pose.x = f.number("robot_x"), pose.y = f.number("robot_y"), pose.phi = f.number("robot_theta");
			f.skip(5, "tv, rv and the safety fields");
		}
		f.need(3, "expected ipc_timestamp, ipc_hostname, logger_timestamp");
		row.time = pose.time = f.time("ipc_timestamp");
		if (!(fov > 0 && fov <= 2 * M_PI)) throw std::invalid_argument(kind + ": field_of_view must be within (0, 2 pi]");
		if (!(std::abs(start) <= 2 * M_PI)) throw std::invalid_argument(kind + ": start_angle must be within [-2 pi, 2 pi]");
		if (!(max_range > 0)) throw std::invalid_argument(kind + ": maximum_range must be > 0");
		addScan(kind, start, fov, max_range, std::move(row));
		if (kind == "ROBOTLASER1") laser_poses.push_back(pose);
	}

	void odom(Fields& f)
	{
		f.need(9, "expected x, y, theta, tv, rv, accel and the times");
		OdometryRow pose;
		pose.x = f.number("x"), pose.y = f.number("y"), pose.phi = f.number("theta");
		f.skip(3, "tv, rv and accel");
		pose.time = f.time("ipc_timestamp");
		if (!log.odometry.empty()) requireTimeAfter(log.odometry.back().time, pose.time, "ODOM time");
		log.odometry.push_back(pose);
	}
};
}  // namespace

CarmenLog readCarmenLog(const std::string& path)
{
	CarmenReader r;
	forEachDataLine(path, "CARMEN log", [&](int, const std::string& line) {
		Fields f(line);
		const std::string kind = f.word();
		if (kind == "FLASER") r.flaser(f);
		else if (kind == "RAWLASER1" || kind == "ROBOTLASER1") r.rawLaser(kind, f);
		else if (kind == "ODOM") r.odom(f);
	});
	CarmenLog log = std::move(r.log);
	if (log.odometry.empty()) log.odometry = std::move(r.laser_poses);
	// A file with none of the messages read is not a CARMEN log (a rawlog, a README).
	if (log.laser.empty() && log.odometry.empty())
		throw std::runtime_error("'" + path + "' holds no CARMEN laser (FLASER, RAWLASER1, ROBOTLASER1) or ODOM message");
	return log;
}

}  // namespace omnirange
