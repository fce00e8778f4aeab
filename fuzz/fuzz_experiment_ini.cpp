// An experiment's ini (omnirange-experiment), every section it reads.
#include "FuzzInput.h"

#include <omnirange_eval/ExperimentConfig.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "experiment.ini");
	omnirange::fuzz::expectEitherResultOrError([&] { (void)omnirange::eval::ExperimentConfig::load(in.path()); });
	return 0;
}
