// A user's own logs (io/LogImport.h, io/CarmenLog.h, train/OCamCalibFile.h):
// the laser and odometry CSVs, the image list, a CARMEN log and OCamCalib's
// calib_results.txt, each parser given the same bytes.
#include "FuzzInput.h"

#include <omnirange/core/CameraModel.h>
#include <omnirange/io/CarmenLog.h>
#include <omnirange/io/LogImport.h>
#include <omnirange/train/OCamCalibFile.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	using namespace omnirange;
	const fuzz::FuzzInput in(data, size, "log.csv");
	fuzz::expectEitherResultOrError([&] { (void)readLaserCsv(in.path()); });
	fuzz::expectEitherResultOrError([&] { (void)readOdometryCsv(in.path()); });
	fuzz::expectEitherResultOrError([&] { (void)listImages("", in.path()); });
	fuzz::expectEitherResultOrError([&] { (void)readCarmenLog(in.path()); });
	fuzz::expectEitherResultOrError([&] { (void)OmniCameraModel(ocamCamera(readOCamCalib(in.path()))); });
	return 0;
}
