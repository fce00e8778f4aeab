// omnirange-scan: see omnirange_apps/ScanApp.h. Parses the command line and runs
// the app; every error ends here as one line on stderr and exit code 1.
#include <omnirange_apps/ScanApp.h>
#include <omnirange_apps/CommandLine.h>

int main(int argc, char** argv)
{
	using omnirange::app::ScanApp;
	return omnirange::app::runApp("omnirange-scan", [&] { ScanApp(ScanApp::parse(argc, argv)).run(); });
}
