#pragma once
// The list of experiments (ini/suite.txt): one line each, "NAME GROUP WHAT",
// read by the scripts that run them and by the summary that tables them.

#include <string>
#include <vector>

namespace omnirange::eval
{
struct SuiteEntry
{
	std::string name;  ///< the experiment's ini is ini/NAME.ini; its report results/NAME/
	std::string group;  ///< main, hard, room or mirror
	std::string description;
};

/** The suite file's entries, in its order. Throws std::runtime_error naming
 * the file and line of a malformed or repeated entry. */
std::vector<SuiteEntry> loadSuite(const std::string& path);

}  // namespace omnirange::eval
