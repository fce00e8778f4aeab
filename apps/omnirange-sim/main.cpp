// omnirange-sim: see omnirange_apps/SimApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/SimApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::SimApp;
	return omnirange::app::runApp("omnirange-sim", [&] { SimApp(SimApp::parse(argc, argv)).run(); });
}
