// omnirange-tuner: see a rawlog through the rangefinder and tune it
// (docs/tuner.md). The command line and the session are checked before any
// window opens: bad input is one line on stderr and exit code 1, as in the
// other apps.
#include "TunerFrame.h"

#include <omnirange_apps/CommandLine.h>


#include <wx/app.h>

#include <iostream>
#include <memory>
#include <stdexcept>

namespace
{
struct Options
{
	omnirange::tuner::SessionOptions session;
	std::string save_to;
	int frame{0};
};

Options parse(int argc, const char* const* argv)
{
	Options o;
	auto& s = o.session;
	TCLAP::CmdLine cmd("omnirange-tuner: see and tune the omnicam rangefinder on a rawlog", ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with omnicam images (and laser scans)", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> ini("c", "config", "ini with the rangefinder's parameters", true, "", "INI", cmd);
	TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, s.section, "NAME", cmd);
	TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file (none: train one in the tuner)", false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> save("", "save-to", "ini that Save writes into (default: the -c ini)", false, "", "INI", cmd);
	TCLAP::ValueArg<int> frame("f", "frame", "frame to show first (0-based)", false, 0, "N", cmd);
	TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images", false, s.omni_label, "LABEL", cmd);
	TCLAP::ValueArg<std::string> laser("", "laser-label", "label of the laser scans", false, s.laser_label, "LABEL", cmd);
	omnirange::app::parseArgs(cmd, argc, argv);
	s.rawlog = in.getValue(), s.ini = ini.getValue(), s.section = section.getValue(), s.histogram = hist.getValue();
	s.omni_label = omni.getValue(), s.laser_label = laser.getValue();
	o.save_to = save.getValue().empty() ? s.ini : save.getValue();
	o.frame = frame.getValue();
	return o;
}

std::unique_ptr<omnirange::tuner::TunerSession> g_session;
Options g_options;

class TunerApp : public wxApp
{
   public:
	bool OnInit() override
	{
		auto* frame = new TunerFrame(*g_session, g_options.save_to, g_options.frame);
		frame->Show();
		return true;
	}
	// The handlers catch what they throw (TunerFrame::bindGuarded); anything
	// else is said on stderr and the window stays, with the user's values.
	bool OnExceptionInMainLoop() override
	{
		try
		{
			throw;
		}
		catch (const std::exception& e)
		{
			std::cerr << "omnirange-tuner: error: " << omnirange::app::errorText(e) << std::endl;
		}
		catch (...)
		{
			std::cerr << "omnirange-tuner: error: an unknown exception" << std::endl;
		}
		return true;
	}
	// The command line was parsed before wx started: wx must not parse it again.
	void OnInitCmdLine(wxCmdLineParser&) override {}
	bool OnCmdLineParsed(wxCmdLineParser&) override { return true; }
};
}  // namespace

wxIMPLEMENT_APP_NO_MAIN(TunerApp);

int main(int argc, char** argv)
{
	return omnirange::app::runApp("omnirange-tuner", [&] {
		g_options = parse(argc, argv);
		if (g_options.frame < 0) throw std::invalid_argument("frame must be >= 0");
		g_session = std::make_unique<omnirange::tuner::TunerSession>(g_options.session);  // reads and checks them
		// Save writes into the ini (the -c one by default), never into what is read, nor the bases under it.
		g_session->requireSaveAllowed(g_options.save_to);
		if (g_options.frame >= g_session->frames())
			throw std::invalid_argument("frame " + std::to_string(g_options.frame) + " is past the rawlog's " +
										std::to_string(g_session->frames()) + " frames");
		int wx_argc = 1;
		char* wx_argv[] = {argv[0], nullptr};
		if (wxEntry(wx_argc, wx_argv) != 0) throw std::runtime_error("the window could not be opened (no display?)");
	});
}
