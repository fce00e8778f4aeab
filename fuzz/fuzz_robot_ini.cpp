// The simulator's robot ini (omnirange-sim --robot).
#include "FuzzInput.h"

#include <omnirange_sim/RobotParams.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "robot.ini");
	omnirange::fuzz::expectEitherResultOrError([&] { (void)omnirange::sim::RobotParams::loadFile(in.path()); });
	return 0;
}
