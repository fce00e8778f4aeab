// omnirange-calibrate: see omnirange_apps/CalibrateApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/CalibrateApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::CalibrateApp;
	return omnirange::app::runApp("omnirange-calibrate", [&] {
		CalibrateApp app(CalibrateApp::parse(argc, argv));
		if (!app.options().rim_images.empty()) app.runRim();
		if (!app.options().checkerboards.empty()) app.runIntrinsics();
		if (!app.options().ocamcalib.empty()) app.runOCamCalib();
		const auto& o = app.options();
		if (o.rim_images.empty() && o.checkerboards.empty() && o.ocamcalib.empty()) app.run();
	});
}
