#pragma once
// Rewrites an observations-only rawlog in MRPT's other format, the one
// rawlog-grabber writes with use_sensoryframes = 1, older datasets use and
// rbpf-slam reads: (action collection, sensory frame) pairs, odometry as the
// actions' increments. Each odometry reading starts a new frame; the frame
// holds the observations that follow it. The images stay where they are (a link).

#include <omnirange/config/SensorLabels.h>

#include <string>

namespace omnirange::eval
{
/** Returns the number of frames written to `out`; the images folder of `in`
 * is linked as out's. Throws std::runtime_error naming the file on a bad rawlog. */
int writeSensoryFrameFormat(const std::string& in, const std::string& out,
							const std::string& odometry_label = kOdometryLabel);

}  // namespace omnirange::eval
