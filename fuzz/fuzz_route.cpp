// Route files (docs/worlds.md).
#include "FuzzInput.h"

#include <omnirange_sim/Route.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "f.route");
	omnirange::fuzz::expectEitherResultOrError([&] { (void)omnirange::sim::loadRoute(in.path()); });
	return 0;
}
