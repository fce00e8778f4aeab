// World files (docs/worlds.md).
#include "FuzzInput.h"

#include <omnirange_sim/World.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "f.world");
	omnirange::fuzz::expectEitherResultOrError([&] { (void)omnirange::sim::loadWorld(in.path()); });
	return 0;
}
