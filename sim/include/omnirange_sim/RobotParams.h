#pragma once
// The simulated robot (docs/worlds.md): an omnicam, a laser, odometry, its
// motion. Read from a robot ini (ini/robot-omnip2dx.ini documents every key).

#include <omnirange/core/CameraModel.h>
#include <omnirange/config/OptionsTable.h>
#include <omnirange_sim/CameraEffects.h>

#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace omnirange::sim
{
struct OmnicamSimParams
{
	CameraParams camera;  ///< the same keys as the rangefinder's camera
	mrpt::poses::CPose3D pose{0, 0, 0.931, 0, 0, 0};  ///< on the robot (pose_* keys)
	double rim_theta{1.85};  ///< [rad] incidence angle at the mirror's rim (default 1.85, 106 deg)
	double centre_offset_u{0};  ///< [px] mirror misalignment: true centre minus cx (default 0)
	double centre_offset_v{0};  ///< [px] the same for cy (default 0)
	double noise_sigma{3.0};  ///< [grey levels] sensor noise per channel (default 3)
	bool antialias{true};  ///< supersample pixels on edges (default true)
	std::string format{"png"};  ///< png | jpg (default png: lossless)
	int jpeg_quality{90};  ///< [1..100] (default 90)
	CameraEffectsParams effects;  ///< what a real camera adds (CameraEffects.h)
	int truth_rays{360};  ///< rays of the TRUTH scan: the rangefinder's scanlines (default 360)
	double truth_max_range{10.0};  ///< [m] the TRUTH scan's reach (default 10)

	static const OptionsTable<OmnicamSimParams>& table();
};

struct LaserSimParams
{
	mrpt::poses::CPose3D pose{0.16, 0, 0.30, 0, 0, 0};  ///< on the robot (pose_* keys)
	int rays{181};  ///< (default 181)
	double fov{3.14159265358979323846};  ///< [rad] (default pi)
	double max_range{19.8};  ///< [m] (default 19.8)
	double sigma{0.005};  ///< [m] range noise (default 0.005)

	static const OptionsTable<LaserSimParams>& table();
};

struct OdometrySimParams
{
	double sigma_dist{0.02};  ///< [-] noise per metre driven (default 0.02)
	double sigma_turn{0.02};  ///< [-] noise per radian turned (default 0.02)
	double yaw_drift{0.01};  ///< [rad/m] systematic yaw drift (default 0.01)

	static const OptionsTable<OdometrySimParams>& table();
};

struct RobotBodyParams
{
	double speed{0.4};  ///< [m/s] (default 0.4)
	double turn_rate{0.6};  ///< [rad/s] (default 0.6)
	double frame_rate{4.0};  ///< [Hz] one image, scan, odometry and GT per frame (default 4)
	double length{0.45};  ///< [m] the body seen below the omnicam (default 0.45)
	double width{0.38};  ///< [m] (default 0.38)
	double height{0.25};  ///< [m] top of the body (default 0.25)
	double clearance{0.30};  ///< [m] nearest a route may pass a solid (default 0.30)
	/// [m] the robot's full height with its camera: a solid with any part below it is struck
	/// (the BODY truth; default 1.0)
	double strike_height{1.0};
	bool own_shadow{false};  ///< the body shades the floor around it as a solid does (default false)
	std::uint32_t seed{1};  ///< all randomness derives from it (default 1)

	static const OptionsTable<RobotBodyParams>& table();
};

struct RobotParams
{
	OmnicamSimParams omnicam;
	LaserSimParams laser;
	OdometrySimParams odometry;
	RobotBodyParams robot;

	/** Sections [omnicam], [laser], [odometry], [robot]; all optional, every
	 * key checked (angles in degrees: keys NAME_deg). Throws
	 * std::invalid_argument naming the section and key. */
	void loadFromConfig(const mrpt::config::CConfigFileBase& cfg);
	/** The robot ini file `path`, checked whole (a repeated key too); throws
	 * std::runtime_error naming the file. */
	static RobotParams loadFile(const std::string& path);
	void validate() const;
};

}  // namespace omnirange::sim
