#pragma once
// The sensor labels of this project's rawlogs (docs/architecture.md), each defined
// once. Every app takes the label it reads or writes as an option whose
// default is one of these.

namespace omnirange
{
inline constexpr const char* kOmnicamLabel = "OMNICAM";  ///< CObservationImage: the omnicam's images
inline constexpr const char* kLaserLabel = "LASER";  ///< CObservation2DRangeScan: the laser
inline constexpr const char* kOdometryLabel = "ODOMETRY";  ///< CObservationOdometry
inline constexpr const char* kGroundTruthLabel = "GT";  ///< CObservationRobotPose: the simulator's true pose
inline constexpr const char* kOmniscanLabel = "OMNISCAN";  ///< CObservation2DRangeScan: the rangefinder's scans
/** CObservation2DRangeScan from the simulator: where the floor really ends
 * along each scanline bearing (sim/FloorTruth.h). */
inline constexpr const char* kTruthLabel = "TRUTH";
/** CObservation2DRangeScan from the simulator: the nearest solid below the
 * robot's strike height along each bearing, what the robot would hit. */
inline constexpr const char* kBodyLabel = "BODY";
/** CObservation2DRangeScan: the laser and the omnicam in one scan (core/ScanFusion.h). */
inline constexpr const char* kFusedLabel = "FUSED";

}  // namespace omnirange
