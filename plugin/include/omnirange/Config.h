#pragma once
// Small helpers shared by the options structs that load from ini files.

#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace omnirange
{
/** Throws std::invalid_argument if `section` holds a key not in `known`,
 * naming the key and the section (a misspelt key must not pass silently). */
void requireKnownKeys(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::vector<std::string>& known);

/** A sensor's pose on the robot from MRPT's keys pose_x, pose_y, pose_z [m]
 * and pose_yaw, pose_pitch, pose_roll [deg]; absent keys keep `def`. */
mrpt::poses::CPose3D readSensorPose(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const mrpt::poses::CPose3D& def);

/** The keys readSensorPose() reads. */
std::vector<std::string> sensorPoseKeys();

/** Throws std::invalid_argument("<section>: <what>") unless `ok`. */
void requireParam(bool ok, const std::string& section, const std::string& what);

}  // namespace omnirange
