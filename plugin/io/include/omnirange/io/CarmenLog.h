#pragma once
// CARMEN's text logs (the robotics toolkit's and many public datasets'
// format), read for omnirange-import: the laser and the odometry in them,
// to be joined with the omnicam's images. One message per line, fields
// separated by blanks, '#' comments; every message ends with
// "ipc_timestamp ipc_hostname logger_timestamp" and the ipc time is used.
// Read: FLASER, ROBOTLASER1, RAWLASER1 (the laser; one kind per log) and
// ODOM. Other messages (PARAM, SYNC, TRUEPOS, ...) are skipped.
//   FLASER n r_1..r_n x y theta odom_x odom_y odom_theta ipc host logger
//   RAWLASER1 type start fov res max_range accuracy mode n r_1..r_n m v_1..v_m ipc host logger
//   ROBOTLASER1 (RAWLASER1's fields) laser_x laser_y laser_theta robot_x robot_y robot_theta
//               tv rv forward_safety side_safety turn_axis ipc host logger
//   ODOM x y theta tv rv accel ipc host logger

#include <omnirange/io/LogImport.h>

#include <string>
#include <vector>

namespace omnirange
{
struct CarmenLog
{
	std::vector<LaserRow> laser;
	/** ODOM's poses; without ODOM messages, the odometry poses the laser
	 * messages carry (FLASER's odom_*, ROBOTLASER1's robot_*). */
	std::vector<OdometryRow> odometry;
	std::string laser_message;  ///< FLASER, RAWLASER1 or ROBOTLASER1; empty: no laser
	/** [rad] The first ray's angle and the field of view; FLASER does not
	 * say them, and CARMEN's front laser is 180 degrees from -90. */
	double start_angle{-1.57079632679489661923}, fov{3.14159265358979323846};
	double max_range{0};  ///< [m] 0: the log does not say (FLASER)
};

/** Throws std::runtime_error("FILE:LINE: what") on a message with too few
 * fields, a number that is not one, a laser whose ray count, field of view
 * or max range changes, or times out of order within a stream. */
CarmenLog readCarmenLog(const std::string& path);

}  // namespace omnirange
