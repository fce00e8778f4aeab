#pragma once
// What several app tests do after training: omnirange-scan, then
// omnirange-accuracy on the frames from `first` on, in process.
#include <omnirange_apps/AccuracyApp.h>
#include <omnirange_apps/ScanApp.h>

#include <string>

namespace omnirange::test
{
inline eval::AccuracyResult scanAndScore(const std::string& ini, const std::string& histogram,
										 const std::string& rawlog, const std::string& dir, int first)
{
	app::ScanApp::Options s;
	s.ini = ini;
	s.histogram = histogram;
	s.scan.input = rawlog;
	s.scan.output = dir + "/scanned.rawlog";
	s.verbosity = mrpt::system::LVL_ERROR;
	app::ScanApp(s).run();
	app::AccuracyApp::Options a;
	a.input = s.scan.output;
	a.output = dir + "/acc";
	a.accuracy.first = first;
	a.verbosity = mrpt::system::LVL_ERROR;
	return app::AccuracyApp(a).run();
}
}  // namespace omnirange::test
