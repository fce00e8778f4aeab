#include "omnirange/Config.h"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <stdexcept>

namespace omnirange
{
void requireKnownKeys(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	const std::vector<std::string>& known)
{
	std::vector<std::string> present;
	cfg.getAllKeys(section, present);
	for (const auto& k : present)
		if (std::find(known.begin(), known.end(), k) == known.end())
			throw std::invalid_argument(
				"unknown key '" + k + "' in section [" + section + "]");
}

mrpt::poses::CPose3D readSensorPose(
	const mrpt::config::CConfigFileBase& c, const std::string& s, const mrpt::poses::CPose3D& def)
{
	using mrpt::DEG2RAD;
	using mrpt::RAD2DEG;
	return {c.read_double(s, "pose_x", def.x()), c.read_double(s, "pose_y", def.y()),
			c.read_double(s, "pose_z", def.z()),
			DEG2RAD(c.read_double(s, "pose_yaw", RAD2DEG(def.yaw()))),
			DEG2RAD(c.read_double(s, "pose_pitch", RAD2DEG(def.pitch()))),
			DEG2RAD(c.read_double(s, "pose_roll", RAD2DEG(def.roll())))};
}

std::vector<std::string> sensorPoseKeys()
{
	return {"pose_x", "pose_y", "pose_z", "pose_yaw", "pose_pitch", "pose_roll"};
}

void requireParam(bool ok, const std::string& section, const std::string& what)
{
	if (!ok) throw std::invalid_argument("[" + section + "] " + what);
}

}  // namespace omnirange
