// Histogram files (omnirange-train's output, omnirange-scan's -H input).
#include "FuzzInput.h"

#include <omnirange/core/ColourModel.h>

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "f.hist");
	omnirange::fuzz::expectEitherResultOrError([&] {
		const auto model = omnirange::ColourModel::load(in.path());
		// A loaded model must answer for any colour.
		const std::uint8_t grey[3] = {128, 128, 128};
		(void)model.floor.probability(model.floor.binner().binOf(grey));
		if (model.hasObstacles()) (void)model.obstacles.probability(model.obstacles.binner().binOf(grey));
	});
	return 0;
}
