#pragma once
// A robot's pose at an instant: what a path, estimated or true, is made of.

#include <mrpt/poses/CPose2D.h>

namespace omnirange::slam
{
struct StampedPose
{
	double t;  ///< [s] timestamp
	mrpt::poses::CPose2D pose;
};

}  // namespace omnirange::slam
