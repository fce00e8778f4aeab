#include "omnirange_sim/RobotParams.h"

#include <omnirange/config/LayeredIni.h>

#include <mrpt/config/CConfigFile.h>

#include <cmath>
#include <filesystem>

namespace omnirange::sim
{
const OptionsTable<OmnicamSimParams>& OmnicamSimParams::table()
{
	using P = OmnicamSimParams;
	static const auto t = OptionsTable<P>()
		.include(CameraParams::table(), [](P& p) -> auto& { return p.camera; })
		.addPose("the omnicam's pose on the robot", [](P& p) -> auto& { return p.pose; })
		.addAngle("rim_theta", "incidence angle at the mirror's rim", [](P& p) -> auto& { return p.rim_theta; })
		.add("centre_offset_u", "px", "mirror misalignment: true centre minus cx", [](P& p) -> auto& { return p.centre_offset_u; })
		.add("centre_offset_v", "px", "the same for cy", [](P& p) -> auto& { return p.centre_offset_v; })
		.add("noise_sigma", "grey levels", "sensor noise per channel", [](P& p) -> auto& { return p.noise_sigma; })
		.add("antialias", "bool", "supersample pixels on edges", [](P& p) -> auto& { return p.antialias; })
		.add("format", "-", "png | jpg", [](P& p) -> auto& { return p.format; })
		.add("jpeg_quality", "1..100", "JPEG quality", [](P& p) -> auto& { return p.jpeg_quality; })
		.add("blur_sigma", "px", "Gaussian blur of the optics (0: none)", [](P& p) -> auto& { return p.effects.blur_sigma; })
		.add("vignetting", "-", "darkening at the mirror's rim, 1 - v (r / r_rim)^2 (0: none)",
			 [](P& p) -> auto& { return p.effects.vignetting; })
		.add("exposure_drift", "-", "amplitude of the exposure's swing along the route (0: none)",
			 [](P& p) -> auto& { return p.effects.exposure_drift; })
		.add("white_balance_drift", "-", "amplitude of the red/blue balance's swing along the route (0: none)",
			 [](P& p) -> auto& { return p.effects.white_balance_drift; })
		.add("drift_period", "frames", "period of both swings", [](P& p) -> auto& { return p.effects.drift_period; })
		.add("bayer", "bool", "RGGB colour filter, demosaiced", [](P& p) -> auto& { return p.effects.bayer; })
		.add("truth_rays", "-", "rays of the TRUTH scan (where the floor really ends)", [](P& p) -> auto& { return p.truth_rays; })
		.add("truth_max_range", "m", "the TRUTH scan's reach", [](P& p) -> auto& { return p.truth_max_range; })
		.renamed("rim_theta", "use rim_theta_deg, in degrees");
	return t;
}

const OptionsTable<LaserSimParams>& LaserSimParams::table()
{
	using P = LaserSimParams;
	static const auto t = OptionsTable<P>()
		.addPose("the laser's pose on the robot", [](P& p) -> auto& { return p.pose; })
		.add("rays", "-", "rays per scan", [](P& p) -> auto& { return p.rays; })
		.addAngle("fov", "field of view", [](P& p) -> auto& { return p.fov; })
		.add("max_range", "m", "largest range", [](P& p) -> auto& { return p.max_range; })
		.add("sigma", "m", "range noise", [](P& p) -> auto& { return p.sigma; })
		.renamed("fov", "use fov_deg, in degrees");
	return t;
}

const OptionsTable<OdometrySimParams>& OdometrySimParams::table()
{
	using P = OdometrySimParams;
	static const auto t = OptionsTable<P>()
		.add("sigma_dist", "-", "noise per metre driven", [](P& p) -> auto& { return p.sigma_dist; })
		.add("sigma_turn", "-", "noise per radian turned", [](P& p) -> auto& { return p.sigma_turn; })
		.addAngle("yaw_drift", "systematic yaw drift per metre driven [deg/m]", [](P& p) -> auto& { return p.yaw_drift; })
		.renamed("yaw_drift", "use yaw_drift_deg, in degrees per metre");
	return t;
}

const OptionsTable<RobotBodyParams>& RobotBodyParams::table()
{
	using P = RobotBodyParams;
	static const auto t = OptionsTable<P>()
		.add("speed", "m/s", "driving speed", [](P& p) -> auto& { return p.speed; })
		.addAngle("turn_rate", "turning rate on the spot [deg/s]", [](P& p) -> auto& { return p.turn_rate; })
		.add("frame_rate", "Hz", "one image, scan, odometry and GT per frame", [](P& p) -> auto& { return p.frame_rate; })
		.add("length", "m", "the body seen below the omnicam", [](P& p) -> auto& { return p.length; })
		.add("width", "m", "the body's width", [](P& p) -> auto& { return p.width; })
		.add("height", "m", "top of the body", [](P& p) -> auto& { return p.height; })
		.add("clearance", "m", "nearest a route may pass a solid", [](P& p) -> auto& { return p.clearance; })
		.add("strike_height", "m", "the robot's full height: a solid with a part below it is struck (BODY)",
			 [](P& p) -> auto& { return p.strike_height; })
		.add("own_shadow", "bool", "the body casts the sun's shadow and darkens the floor at its foot",
			 [](P& p) -> auto& { return p.own_shadow; })
		.add("seed", "-", "all randomness derives from it", [](P& p) -> auto& { return p.seed; })
		.renamed("turn_rate", "use turn_rate_deg, in degrees per second");
	return t;
}

void RobotParams::loadFromConfig(const mrpt::config::CConfigFileBase& c)
{
	// Every section is optional: a robot ini overrides only what it names.
	const auto section = [&](const auto& table, auto& params, const std::string& name) {
		if (c.sectionExists(name)) table.load(params, c, name);
	};
	section(OmnicamSimParams::table(), omnicam, "omnicam");
	section(LaserSimParams::table(), laser, "laser");
	section(OdometrySimParams::table(), odometry, "odometry");
	section(RobotBodyParams::table(), robot, "robot");
	validate();
}

RobotParams RobotParams::loadFile(const std::string& path)
{
	if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": cannot open robot ini");
	RobotParams r;
	// Over its base, as every ini of ours (`base = robot-hyperbolic.ini`): each file checked, the merge read.
	const LayeredIni ini = readLayeredIni(path);
	for (const auto& file : ini.files) requireOnlySections(file, {"omnicam", "laser", "odometry", "robot"});
	try
	{
		r.loadFromConfig(*ini.merged);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(namingItsFile(ini, path, e));
	}
	return r;
}

void RobotParams::validate() const
{
	try
	{
		omnicam.camera.validate();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(std::string("[omnicam] ") + e.what());
	}
	const auto& o = omnicam;
	require(o.rim_theta > 1.0 && o.rim_theta < 3.0, "[omnicam] rim_theta_deg must be in (57.3, 171.9)");
	require(o.noise_sigma >= 0 && o.noise_sigma <= 255, "[omnicam] noise_sigma must be within [0, 255]");
	require(o.format == "jpg" || o.format == "png", "[omnicam] format must be jpg or png");
	require(o.jpeg_quality >= 1 && o.jpeg_quality <= 100, "[omnicam] jpeg_quality must be in 1..100");
	const auto& fx = o.effects;
	require(fx.blur_sigma >= 0 && fx.blur_sigma <= 20, "[omnicam] blur_sigma must be within [0, 20] px");
	require(fx.vignetting >= 0 && fx.vignetting <= 1, "[omnicam] vignetting must be within [0, 1]");
	require(fx.exposure_drift >= 0 && fx.exposure_drift < 1, "[omnicam] exposure_drift must be within [0, 1)");
	require(fx.white_balance_drift >= 0 && fx.white_balance_drift < 1,
			"[omnicam] white_balance_drift must be within [0, 1)");
	require(fx.drift_period >= 1, "[omnicam] drift_period must be >= 1 frame");
	require(o.truth_rays >= 2 && o.truth_rays <= 36000, "[omnicam] truth_rays must be within [2, 36000]");
	require(o.truth_max_range > 0 && o.truth_max_range <= 1000, "[omnicam] truth_max_range must be within (0, 1000] m");
	require(laser.rays >= 2 && laser.rays <= 100000, "[laser] rays must be within [2, 100000]");
	require(laser.fov > 0 && laser.fov <= 6.2832, "[laser] fov_deg must be in (0, 360]");
	require(laser.max_range > 0 && laser.max_range <= 1000, "[laser] max_range must be within (0, 1000] m");
	require(laser.sigma >= 0 && laser.sigma <= 10, "[laser] sigma must be within [0, 10] m");
	require(odometry.sigma_dist >= 0 && odometry.sigma_dist <= 1 && odometry.sigma_turn >= 0 && odometry.sigma_turn <= 1,
			"[odometry] sigma_dist and sigma_turn must be within [0, 1]");
	require(std::abs(odometry.yaw_drift) <= M_PI, "[odometry] yaw_drift_deg must be within [-180, 180] deg/m");
	const auto& r = robot;
	// A robot that creeps or films too often makes millions of frames: bounded so
	// that a typo fails here, not after memory runs out.
	require(r.speed >= 0.01 && r.speed <= 10, "[robot] speed must be within [0.01, 10] m/s");
	constexpr double deg = M_PI / 180;
	require(r.turn_rate >= 1 * deg && r.turn_rate <= 1000 * deg,
			"[robot] turn_rate_deg must be within [1, 1000] deg/s");
	require(r.frame_rate >= 0.01 && r.frame_rate <= 100, "[robot] frame_rate must be within [0.01, 100] Hz");
	require(r.length > 0 && r.width > 0 && r.height > 0 && r.length <= 10 && r.width <= 10,
			"[robot] the body's size must be within (0, 10] m");
	require(r.height < o.camera.h, "[robot] the body must be lower than the omnicam's h");
	require(r.clearance >= 0 && r.clearance <= 10, "[robot] clearance must be within [0, 10] m");
	require(r.strike_height > 0 && r.strike_height <= 100, "[robot] strike_height must be within (0, 100] m");
}

}  // namespace omnirange::sim
