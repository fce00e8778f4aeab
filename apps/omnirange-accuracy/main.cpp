// omnirange-accuracy: see omnirange_apps/AccuracyApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/AccuracyApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::AccuracyApp;
	return omnirange::app::runApp("omnirange-accuracy", [&] { AccuracyApp(AccuracyApp::parse(argc, argv)).run(); });
}
