#pragma once
// The world file reader's view of one statement: its "key=value" tokens,
// read with checks whose errors name the file and line. Private to sim/src.

#include <array>
#include <cmath>
#include <sstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace omnirange::sim
{
/** One line's "key=value" tokens, with checks that name the line. */
class Fields
{
   public:
	Fields(std::string where, const std::vector<std::string>& tokens) : where_(std::move(where))
	{
		for (const auto& t : tokens)
		{
			const auto eq = t.find('=');
			if (eq == std::string::npos || eq == 0)
				throw error("expected key=value, got '" + t + "'");
			// The second would win silently: a typo's copy of a key, not a choice.
			if (!kv_.emplace(t.substr(0, eq), t.substr(eq + 1)).second)
				throw error("key '" + t.substr(0, eq) + "' given twice");
		}
	}
	std::runtime_error error(const std::string& what) const
	{
		return std::runtime_error(where_ + ": " + what);
	}
	bool has(const std::string& k) const { return kv_.count(k) != 0; }
	std::string str(const std::string& k) const
	{
		used_.insert(k);
		const auto it = kv_.find(k);
		if (it == kv_.end()) throw error("missing key '" + k + "'");
		return it->second;
	}
	double num(const std::string& k) const
	{
		const std::string s = str(k);
		char* end = nullptr;
		const double v = std::strtod(s.c_str(), &end);
		if (end == s.c_str() || *end != '\0' || !std::isfinite(v))
			throw error("key '" + k + "' is not a number: '" + s + "'");
		return v;
	}
	double num(const std::string& k, double def) const { return has(k) ? num(k) : def; }
	double positive(const std::string& k) const
	{
		const double v = num(k);
		if (!(v > 0)) throw error("key '" + k + "' must be > 0, not " + str(k));
		return v;
	}
	std::array<double, 3> rgb(const std::string& k) const
	{
		std::array<double, 3> c{};
		std::istringstream s(str(k));
		char comma;
		if (!(s >> c[0] >> comma >> c[1] >> comma >> c[2]))
			throw error("key '" + k + "' must be R,G,B");
		for (double v : c)
			if (v < 0 || v > 255) throw error("key '" + k + "' has a value outside 0..255");
		return c;
	}
	/** Throws on a key nothing read (a typo must not pass silently). */
	void requireAllUsed() const
	{
		for (const auto& [k, v] : kv_)
			if (!used_.count(k)) throw error("unknown key '" + k + "'");
	}

   private:
	std::string where_;
	std::map<std::string, std::string> kv_;
	mutable std::set<std::string> used_;
};

}  // namespace omnirange::sim
