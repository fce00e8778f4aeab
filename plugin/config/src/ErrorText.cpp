#include "omnirange/config/ErrorText.h"

#include <sstream>

namespace omnirange
{
namespace
{
/** The length of the UTF-8 sequence at `s[i]`, or 0 if it is not one. */
std::size_t utf8Length(const std::string& s, std::size_t i)
{
	const auto c = static_cast<unsigned char>(s[i]);
	const std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
	if (n == 0 || i + n > s.size()) return 0;
	for (std::size_t k = 1; k < n; ++k)
		if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
	return n;
}
}  // namespace

std::string oneLine(const std::string& s)
{
	std::string out;
	out.reserve(s.size());
	for (std::size_t i = 0; i < s.size();)
	{
		const auto c = static_cast<unsigned char>(s[i]);
		if (c == '\n' || c == '\r' || c == '\t') out += ' ', ++i;
		else if (c < 0x20 || c == 0x7F) out += '?', ++i;
		else if (c < 0x80) out += s[i++];
		else if (const std::size_t n = utf8Length(s, i); n > 0) out += s.substr(i, n), i += n;
		else out += '?', ++i;
	}
	return out;
}

std::string mrptMessages(const std::string& text)
{
	std::istringstream in(text);
	std::string messages, location;
	bool in_message = false;  // a message goes on over the lines after its tag, up to a blank one
	for (std::string line; std::getline(in, line);)
	{
		if (!line.empty() && line.back() == '\r') line.pop_back();
		const auto from = line.find_first_not_of(' ');
		if (from == std::string::npos || line.rfind("Location:", 0) == 0 || line.rfind("Call stack", 0) == 0)
			in_message = false;
		else if (in_message)
			messages += " " + line.substr(from);
		for (const std::string tag : {"Message:", "Location:"})
			if (line.rfind(tag, 0) == 0)
			{
				const auto start = line.find_first_not_of(' ', tag.size());
				if (start == std::string::npos) continue;
				std::string& to = tag == "Message:" ? messages : location;
				to += (to.empty() ? "" : "; ") + line.substr(start);
				in_message = tag == "Message:";
			}
	}
	// Some of MRPT's errors carry their text in the location line only.
	return messages.empty() ? location : messages;
}

std::string errorInOneLine(const std::string& text)
{
	if (const auto block = text.find("==== MRPT exception ===="); block != std::string::npos)
		if (const std::string m = mrptMessages(text); !m.empty()) return oneLine(text.substr(0, block) + "MRPT: " + m);
	return oneLine(text);
}
}  // namespace omnirange
