#pragma once
// Error text from libraries made into one line a user can read: MRPT's
// framed exception blocks reduced to their messages, and bytes that are not
// text (a class name read from a damaged file) shown as '?'.

#include <string>

namespace omnirange
{
/** `s` on one line: line breaks and tabs become spaces, other control
 * characters and bytes that are not UTF-8 become '?'. */
std::string oneLine(const std::string& s);

/** MRPT's exception text ("==== MRPT exception ====", "Message: ...",
 * "Location: ...", a call stack) as its messages, innermost last ("; "
 * between them); its location when it has no message; "" when `text` is
 * not MRPT's. */
std::string mrptMessages(const std::string& text);

/** `text` on one line, an MRPT exception block in it as "MRPT: " and its
 * messages (what was said before the block, the file a caller names, kept). */
std::string errorInOneLine(const std::string& text);
}  // namespace omnirange
