#include "omnirange_sim/RobotParams.h"

#include <omnirange/Config.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>

namespace omnirange::sim
{
namespace
{
std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b)
{
	a.insert(a.end(), b.begin(), b.end());
	return a;
}
}  // namespace

void RobotParams::loadFromConfig(const mrpt::config::CConfigFileBase& c)
{
	{
		const std::string s = "omnicam";
		requireKnownKeys(c, s, plus(plus(CameraParams::keys(), sensorPoseKeys()),
									{"rim_theta", "centre_offset_u", "centre_offset_v", "noise_sigma",
									 "antialias", "format", "jpeg_quality"}));
		auto& o = omnicam;
		o.camera.loadFromConfig(c, s);
		o.pose = readSensorPose(c, s, o.pose);
		o.rim_theta = c.read_double(s, "rim_theta", o.rim_theta);
		o.centre_offset_u = c.read_double(s, "centre_offset_u", o.centre_offset_u);
		o.centre_offset_v = c.read_double(s, "centre_offset_v", o.centre_offset_v);
		o.noise_sigma = c.read_double(s, "noise_sigma", o.noise_sigma);
		o.antialias = c.read_bool(s, "antialias", o.antialias);
		o.format = c.read_string(s, "format", o.format);
		o.jpeg_quality = c.read_int(s, "jpeg_quality", o.jpeg_quality);
	}
	{
		const std::string s = "laser";
		requireKnownKeys(c, s, plus(sensorPoseKeys(), {"rays", "fov", "max_range", "sigma"}));
		laser.pose = readSensorPose(c, s, laser.pose);
		laser.rays = c.read_int(s, "rays", laser.rays);
		laser.fov = c.read_double(s, "fov", laser.fov);
		laser.max_range = c.read_double(s, "max_range", laser.max_range);
		laser.sigma = c.read_double(s, "sigma", laser.sigma);
	}
	{
		const std::string s = "odometry";
		requireKnownKeys(c, s, {"sigma_dist", "sigma_turn", "yaw_drift"});
		odometry.sigma_dist = c.read_double(s, "sigma_dist", odometry.sigma_dist);
		odometry.sigma_turn = c.read_double(s, "sigma_turn", odometry.sigma_turn);
		odometry.yaw_drift = c.read_double(s, "yaw_drift", odometry.yaw_drift);
	}
	{
		const std::string s = "robot";
		requireKnownKeys(c, s, {"speed", "turn_rate", "frame_rate", "length", "width", "height",
								"clearance", "seed"});
		auto& r = robot;
		r.speed = c.read_double(s, "speed", r.speed);
		r.turn_rate = c.read_double(s, "turn_rate", r.turn_rate);
		r.frame_rate = c.read_double(s, "frame_rate", r.frame_rate);
		r.length = c.read_double(s, "length", r.length);
		r.width = c.read_double(s, "width", r.width);
		r.height = c.read_double(s, "height", r.height);
		r.clearance = c.read_double(s, "clearance", r.clearance);
		r.seed = static_cast<std::uint32_t>(c.read_uint64_t(s, "seed", r.seed));
	}
	validate();
}

void RobotParams::validate() const
{
	omnicam.camera.validate();
	const auto& o = omnicam;
	requireParam(o.rim_theta > 1.0 && o.rim_theta < 3.0, "omnicam", "rim_theta must be in (1, 3) rad");
	requireParam(o.noise_sigma >= 0, "omnicam", "noise_sigma must be >= 0");
	requireParam(o.format == "jpg" || o.format == "png", "omnicam", "format must be jpg or png");
	requireParam(o.jpeg_quality >= 1 && o.jpeg_quality <= 100, "omnicam", "jpeg_quality must be in 1..100");
	requireParam(laser.rays >= 2, "laser", "rays must be >= 2");
	requireParam(laser.fov > 0 && laser.fov <= 6.2832, "laser", "fov must be in (0, 2 pi] rad");
	requireParam(laser.max_range > 0, "laser", "max_range must be > 0 m");
	requireParam(laser.sigma >= 0, "laser", "sigma must be >= 0 m");
	requireParam(odometry.sigma_dist >= 0 && odometry.sigma_turn >= 0, "odometry", "noise must be >= 0");
	const auto& r = robot;
	requireParam(r.speed > 0 && r.turn_rate > 0 && r.frame_rate > 0, "robot",
				 "speed, turn_rate and frame_rate must be > 0");
	requireParam(r.length > 0 && r.width > 0 && r.height > 0, "robot", "the body's size must be > 0 m");
	requireParam(r.height < o.camera.h, "robot", "the body must be lower than the omnicam's h");
	requireParam(r.clearance >= 0, "robot", "clearance must be >= 0 m");
}

}  // namespace omnirange::sim
