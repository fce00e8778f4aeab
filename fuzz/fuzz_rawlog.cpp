// Rawlogs (both formats, gzip or not) through the one read loop, with the
// images decoded as omnirange-scan decodes them.
#include "FuzzInput.h"

#include <omnirange/io/ObservationImage.h>
#include <omnirange/io/RawlogProcessor.h>

#include <mrpt/obs/CObservationImage.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	const omnirange::fuzz::FuzzInput in(data, size, "f.rawlog");
	omnirange::fuzz::expectEitherResultOrError([&] {
		omnirange::RawlogProcessor loop(in.path());
		loop.on<mrpt::obs::CObservationImage>("", [](const mrpt::obs::CObservationImage::Ptr& image) {
			omnirange::fuzz::expectEitherResultOrError([&] { (void)omnirange::decodeImage(*image); });
		});
		loop.run();
	});
	return 0;
}
