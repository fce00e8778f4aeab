// omnirange-calibrate: see omnirange_apps/CalibrateApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/CalibrateApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::CalibrateApp;
	return omnirange::app::runApp("omnirange-calibrate", [&] {
		CalibrateApp(CalibrateApp::parse(argc, argv)).runModes();
	});
}
