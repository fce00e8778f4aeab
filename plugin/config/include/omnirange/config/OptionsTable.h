#pragma once
// One table per options struct: for every field its ini key, unit, meaning
// and a way to parse and print it; the default is the struct's in-class
// initialiser, so it exists in one place. The table loads a section strictly
// (an unknown, renamed or unparsable key is an error that names the section
// and the key), prints the options at start-up, and gives the docs check its
// keys and defaults.
//
// Keys equal member names. An angle is in degrees in the ini and in radians
// in memory; its key is the member's name plus "_deg". A sensor's pose on
// the robot uses MRPT's own keys (pose_x, pose_y, pose_z [m]; pose_yaw,
// pose_pitch, pose_roll [deg]).

#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <istream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace mrpt::config
{
class CConfigFileBase;
}

namespace omnirange
{
/** A key's value or name refused, with the key: a layered ini (LayeredIni.h)
 * can then name the file that set it rather than the one read. */
struct KeyError : std::invalid_argument
{
	KeyError(const std::string& what, std::string section_, std::string key_)
		: std::invalid_argument(what), section(std::move(section_)), key(std::move(key_))
	{
	}
	std::string section, key;  ///< as the file wrote them
};

/** Throws std::invalid_argument(what) unless ok: the way validate() methods fail. */
inline void require(bool ok, const std::string& what)
{
	if (!ok) throw std::invalid_argument(what);
}

/** Strict parsing of one ini value; each throws std::invalid_argument saying what was expected. */
double parseDouble(const std::string& text);  ///< finite; no unit suffix, no comma
int parseInt(const std::string& text);  ///< a whole number that fits an int
std::uint32_t parseUint32(const std::string& text);  ///< a whole number in [0, 2^32)
bool parseBool(const std::string& text);  ///< true/false, yes/no, 1/0
/** [s] A time as logs write it: decimal seconds ("1700000000.25"), no sign,
 * exponent or hex, within MRPT's clock (below kMaxTime). */
double parseTime(const std::string& text);
inline constexpr double kMaxTime = 1e11;
/** [m] A sensor's offset on its robot (pose_x, pose_y, pose_z, --laser-pose):
 * far larger is a typo, and past MRPT's matching ranges it crashes icp. */
inline constexpr double kMaxMountOffset = 100.0;
/** [deg] A sensor's angles on its robot. */
inline constexpr double kMaxMountAngle = 360.0;
/** parseDouble() within [-limit, limit]; the error names the range. */
double parseWithin(const std::string& text, double limit);
/** Numbers separated by blanks, each as parseDouble() takes it; "" is none. */
std::vector<double> parseDoubles(const std::string& text);
std::string formatDouble(double v);
std::string formatDoubles(const std::vector<double>& v);  ///< blank-separated
/** `s` without leading and trailing blanks (spaces, tabs, CR, LF). */
std::string trimmed(const std::string& s);
/** The items with ", " between them: "a, b, c". */
std::string joined(const std::vector<std::string>& items);

/** Throws std::runtime_error("the WHAT 'PATH' is not a regular file") when
 * `path` is a FIFO, a device, a folder or a kernel file, which a reader
 * would block on or read without end. A missing file is left to the
 * reader's own message. */
void requireRegularFile(const std::string& path, const std::string& what);
/** `path` is a file of the kernel's (/proc, /sys): it looks regular, but
 * may never end or block when read (/proc/kmsg). requireRegularFile()
 * refuses it too. */
bool isKernelFile(const std::string& path);

/** Throws std::invalid_argument("WHAT 'F' is given twice (also as 'E')")
 * when a file of `files` is there twice, through a link or another
 * spelling: one photograph would count as two. */
void requireNamedOnce(const std::vector<std::string>& files, const std::string& what);

/** [bytes] The largest ini read (MRPT's reader holds it whole; ours are a few kB). */
inline constexpr std::uintmax_t kMaxIniBytes = std::uintmax_t(1) << 20;

/** [bytes] The longest line a text file of ours may have (1 MB: a laser row of
 * 10,000 ranges is about 100 kB). */
inline constexpr std::size_t kMaxLineBytes = std::size_t(1) << 20;

/** std::getline() for our text files: false at the end; throws
 * std::runtime_error("PATH:LINE: a line of more than 1 MB ...") rather than
 * reading a line without end. */
bool readCappedLine(std::istream& in, std::string& line, const std::string& path, int line_number,
					const std::string& what);

/** Calls `row(line_number, text)` for every line of the text file `path`
 * that is neither blank nor a '#' comment, trimmed. A std::invalid_argument
 * from `row` becomes std::runtime_error("PATH:LINE: what"). Throws
 * std::runtime_error("cannot read the WHAT 'PATH'") if the file cannot be
 * opened. Returns how many lines `row` was given. */
int forEachDataLine(const std::string& path, const std::string& what,
					const std::function<void(int, const std::string&)>& row);

/** What one line of an ini file is: a section header (`name` the section),
 * a "key = value" line (`name` the key), a comment or blank (Other), or
 * none of these (Malformed: "threshold 0.05", "threshold: 0.05", binary). */
struct IniLine
{
	enum class Kind
	{
		Other,
		Section,
		Key,
		Malformed
	} kind{Kind::Other};
	std::string name;
};
IniLine parseIniLine(const std::string& line);

/** The values a number may take: from lo to hi, either end open or closed.
 * The one place a key's range is written: loading, validate(), the docs
 * check and the tuner's controls all read it from the options table. */
struct Range
{
	double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
	bool lo_open = false, hi_open = false;

	// constexpr: a range a header names (kThresholdRange) is set before any table reads it.
	static constexpr Range closed(double lo, double hi) { return {lo, hi, false, false}; }  ///< [lo, hi]
	static constexpr Range openLow(double lo, double hi) { return {lo, hi, true, false}; }  ///< (lo, hi]
	static constexpr Range openHigh(double lo, double hi) { return {lo, hi, false, true}; }  ///< [lo, hi)
	static constexpr Range open(double lo, double hi) { return {lo, hi, true, true}; }  ///< (lo, hi)
	static constexpr Range atLeast(double lo) { return closed(lo, std::numeric_limits<double>::infinity()); }
	static constexpr Range above(double lo) { return open(lo, std::numeric_limits<double>::infinity()); }
	static constexpr Range finite() { return Range(); }

	bool contains(double v) const
	{
		return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi) && v == v && std::abs(v) != kInf;
	}
	/** "within [0, 1]", ">= 1", "> 0", "finite": what a message or the docs say. */
	std::string text() const;

   private:
	static constexpr double kInf = std::numeric_limits<double>::infinity();
};

struct FieldInfo
{
	std::string key, unit, doc;
	/** Numbers only: the values allowed (each element, for a list). */
	std::optional<Range> range;
	/** Enums only: every name the key takes. */
	std::vector<std::string> choices;
	/** "must be within [0, 1] px": the key's range as a message says it. */
	std::string rangeMessage() const;
};

template <class S>
class OptionsTable
{
   public:
	struct Field
	{
		FieldInfo info;
		std::function<void(S&, const std::string&)> parse;
		std::function<std::string(const S&)> print;
		/** A number's value as the ini writes it (a list's every element); none for other kinds. */
		std::function<std::vector<double>(const S&)> numbers;

		/** Whether the field's value in `s` lies in its range (always, without one). */
		bool inRange(const S& s) const
		{
			if (info.range)
				for (const double v : numbers(s))
					if (!info.range->contains(v)) return false;
			return true;
		}
		/** Parses `text` into `s` and checks the range, as loading an ini does;
		 * throws std::invalid_argument saying why the text is refused. */
		void set(S& s, const std::string& text) const
		{
			parse(s, text);
			if (!inRange(s)) throw std::invalid_argument(info.rangeMessage());
		}
	};

	/** A field of type double, int, bool, std::string or std::vector<double>, or an enum with
	 * toString() and `from_string`. `get` maps the struct to the member. */
	template <class Get>
	OptionsTable& add(const std::string& key, const std::string& unit, const std::string& doc, Get get)
	{
		using T = std::remove_reference_t<decltype(get(std::declval<S&>()))>;
		Field f{{key, unit, doc, {}, {}}, {}, {}, {}};
		f.parse = [get](S& s, const std::string& t) { get(s) = parseAs<T>(t); };
		f.print = [get](const S& s) { return printAs(get(const_cast<S&>(s))); };
		if constexpr (std::is_same_v<T, std::vector<double>>)
			f.numbers = [get](const S& s) { return get(const_cast<S&>(s)); };
		else if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
			f.numbers = [get](const S& s) { return std::vector<double>{static_cast<double>(get(const_cast<S&>(s)))}; };
		fields_.push_back(std::move(f));
		return *this;
	}
	/** An enum with toString(): `from_string` parses a name, `all` lists every value. */
	template <class Get, class FromString, class E>
	OptionsTable& addEnum(const std::string& key, const std::string& doc, Get get, FromString from_string,
						  std::initializer_list<E> all)
	{
		Field f{{key, "-", doc, {}, {}}, {}, {}, {}};
		for (const E e : all) f.info.choices.push_back(toString(e));
		f.parse = [get, from_string](S& s, const std::string& t) { get(s) = from_string(t); };
		f.print = [get](const S& s) { return toString(get(const_cast<S&>(s))); };
		fields_.push_back(std::move(f));
		return *this;
	}
	/** An angle: key `member`_deg in degrees, the member in radians. */
	template <class Get>
	OptionsTable& addAngle(const std::string& member, const std::string& doc, Get get)
	{
		Field f{{member + "_deg", "deg", doc, {}, {}}, {}, {}, {}};
		f.parse = [get](S& s, const std::string& t) { get(s) = parseDouble(t) * kDegToRad; };
		f.print = [get](const S& s) { return formatDouble(get(const_cast<S&>(s)) / kDegToRad); };
		f.numbers = [get](const S& s) { return std::vector<double>{get(const_cast<S&>(s)) / kDegToRad}; };
		fields_.push_back(std::move(f));
		return *this;
	}
	/** The values the field added last may take (in the ini's units): load()
	 * and requireRanges() refuse any other. */
	OptionsTable& within(const Range& r)
	{
		if (fields_.empty() || !fields_.back().numbers) throw std::logic_error("within() follows a numeric field");
		fields_.back().info.range = r;
		return *this;
	}
	/** A sensor pose: MRPT's pose_x ... pose_roll keys. */
	template <class Get>
	OptionsTable& addPose(const std::string& doc, Get get);
	/** Every field of `sub`, reached through `get`. */
	template <class Sub, class Get>
	OptionsTable& include(const OptionsTable<Sub>& sub, Get get)
	{
		for (const auto& sf : sub.fields())
		{
			Field f{sf.info, [get, p = sf.parse](S& s, const std::string& t) { p(get(s), t); },
					[get, p = sf.print](const S& s) { return p(get(const_cast<S&>(s))); }, {}};
			if (sf.numbers) f.numbers = [get, n = sf.numbers](const S& s) { return n(get(const_cast<S&>(s))); };
			fields_.push_back(std::move(f));
		}
		for (const auto& r : sub.renamed_) renamed_.push_back(r);
		return *this;
	}
	/** A key that older inis used: loading it fails and says what replaced it. */
	OptionsTable& renamed(const std::string& old_key, const std::string& instead)
	{
		renamed_.push_back({old_key, instead});
		return *this;
	}

	/** Reads every key of `section` present in `cfg` into `s` (absent keys
	 * keep their value). Keys in `also_allowed` are skipped. Throws
	 * std::invalid_argument("[section] key: why"). */
	void load(S& s, const mrpt::config::CConfigFileBase& cfg, const std::string& section,
			  const std::vector<std::string>& also_allowed = {}) const;
	/** Throws std::invalid_argument("KEY must be within [lo, hi] UNIT") at the
	 * first field of `s` outside its range: validate()'s share that needs no
	 * other field. */
	void requireRanges(const S& s) const
	{
		for (const auto& f : fields_)
			if (!f.inRange(s)) throw std::invalid_argument(f.info.key + " " + f.info.rangeMessage());
	}
	/** The field of `key`; throws std::logic_error if there is none. */
	const Field& field(const std::string& key) const
	{
		for (const auto& f : fields_)
			if (f.info.key == key) return f;
		throw std::logic_error("no option '" + key + "'");
	}
	/** One "key = value" line per field, in ini syntax. */
	std::string print(const S& s) const;
	/** "key=value" for each field of `s` that prints unlike in `defaults`, blank-separated
	 * ("(all defaults)" if none): the one line a program shows of its options. */
	std::string printChanges(const S& s, const S& defaults) const
	{
		std::string line;
		for (const auto& f : fields_)
			if (const std::string v = f.print(s); v != f.print(defaults))
				line += (line.empty() ? "" : " ") + f.info.key + "=" + v;
		return line.empty() ? "(all defaults)" : line;
	}
	std::vector<std::string> keys() const;
	const std::vector<Field>& fields() const { return fields_; }
	/** "[unit] meaning" per key: the comment a key written into a user's ini gets. */
	std::map<std::string, std::string> comments() const
	{
		std::map<std::string, std::string> m;
		for (const auto& f : fields_)
			m[f.info.key] = "[" + f.info.unit + "] " + f.info.doc + (f.info.range ? " (" + f.info.range->text() + ")" : "");
		return m;
	}

   private:
	template <class>
	friend class OptionsTable;
	static constexpr double kDegToRad = 0.017453292519943295;

	template <class T>
	static T parseAs(const std::string& t)
	{
		if constexpr (std::is_same_v<T, double>) return parseDouble(t);
		else if constexpr (std::is_same_v<T, int>) return parseInt(t);
		else if constexpr (std::is_same_v<T, bool>) return parseBool(t);
		else if constexpr (std::is_same_v<T, std::uint32_t>) return parseUint32(t);
		else if constexpr (std::is_same_v<T, std::vector<double>>) return parseDoubles(t);
		else return T(t);
	}
	template <class T>
	static std::string printAs(const T& v)
	{
		if constexpr (std::is_same_v<T, double>) return formatDouble(v);
		else if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
		else if constexpr (std::is_integral_v<T>) return std::to_string(v);
		else if constexpr (std::is_same_v<T, std::vector<double>>) return formatDoubles(v);
		else return std::string(v);
	}

	std::vector<Field> fields_;
	std::vector<std::pair<std::string, std::string>> renamed_;
};

/** Throws std::runtime_error("FILE:LINE: ...") if a key appears twice in
 * one section of the ini file `path`, in any mix of upper and lower case
 * (MRPT's reader keeps the last one silently), if a line is Malformed
 * (MRPT's reader skips it silently), if a key stands above every section
 * (other than `base`) or under `[]`, if the file holds no key at all, or if
 * it cannot be read. */
void requireNoRepeatedKeys(const std::string& path);
/** The same, for an ini about to be written into: an empty one passes.
 * Returns how many keys it holds. */
int requireWellFormedIni(const std::string& path);
/** Throws std::runtime_error("FILE:LINE: ...") at a section not in `known`:
 * for files read by this project alone, where a misspelt section would
 * otherwise leave all its keys at their defaults. */
void requireOnlySections(const std::string& path, const std::vector<std::string>& known);

/** Whether two keys (or section names) are one as MRPT reads them: in any mix of case. */
bool sameKey(const std::string& a, const std::string& b);
/** `s` in lower case (ASCII): a key as MRPT compares it. */
std::string lowercase(std::string s);

/** The parts of load() that do not depend on the struct: the section's
 * keys, each checked against `known` and `renamed`. Returns the keys present. */
std::vector<std::string> checkSectionKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
										  const std::vector<std::string>& known,
										  const std::vector<std::pair<std::string, std::string>>& renamed);
std::string readRawValue(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
						 const std::string& key);

template <class S>
template <class Get>
OptionsTable<S>& OptionsTable<S>::addPose(const std::string& doc, Get get)
{
	using mrpt::poses::CPose3D;
	const auto linear = [&](const std::string& key, int axis) {
		Field f{{key, "m", doc, {}, {}}, {}, {}, {}};
		f.parse = [get, axis](S& s, const std::string& t) {
			const double v = parseWithin(t, kMaxMountOffset);
			CPose3D& p = get(s);
			axis == 0 ? p.x(v) : axis == 1 ? p.y(v) : p.z(v);
		};
		f.print = [get, axis](const S& s) { return formatDouble(get(const_cast<S&>(s))[axis]); };
		f.numbers = [get, axis](const S& s) { return std::vector<double>{get(const_cast<S&>(s))[axis]}; };
		f.info.range = Range::closed(-kMaxMountOffset, kMaxMountOffset);
		fields_.push_back(std::move(f));
	};
	linear("pose_x", 0), linear("pose_y", 1), linear("pose_z", 2);
	// Yaw, pitch, roll: set one, keep the other two.
	const auto angular = [&](const std::string& key, int which) {
		Field f{{key, "deg", doc, {}, {}}, {}, {}, {}};
		f.parse = [get, which](S& s, const std::string& t) {
			CPose3D& p = get(s);
			double ypr[3] = {p.yaw(), p.pitch(), p.roll()};
			ypr[which] = parseWithin(t, kMaxMountAngle) * kDegToRad;
			p.setYawPitchRoll(ypr[0], ypr[1], ypr[2]);
		};
		f.print = [get, which](const S& s) {
			const CPose3D& p = get(const_cast<S&>(s));
			const double ypr[3] = {p.yaw(), p.pitch(), p.roll()};
			return formatDouble(ypr[which] / kDegToRad);
		};
		f.numbers = [get, which](const S& s) {
			const CPose3D& p = get(const_cast<S&>(s));
			return std::vector<double>{(which == 0 ? p.yaw() : which == 1 ? p.pitch() : p.roll()) / kDegToRad};
		};
		f.info.range = Range::closed(-kMaxMountAngle, kMaxMountAngle);
		fields_.push_back(std::move(f));
	};
	angular("pose_yaw", 0), angular("pose_pitch", 1), angular("pose_roll", 2);
	return *this;
}

template <class S>
void OptionsTable<S>::load(S& s, const mrpt::config::CConfigFileBase& cfg, const std::string& section,
						   const std::vector<std::string>& also_allowed) const
{
	std::vector<std::string> known = keys();
	known.insert(known.end(), also_allowed.begin(), also_allowed.end());
	const auto present = checkSectionKeys(cfg, section, known, renamed_);
	for (const auto& f : fields_)
	{
		bool found = false;  // in any mix of case, as MRPT finds it
		for (const auto& k : present) found = found || sameKey(k, f.info.key);
		if (!found) continue;
		const std::string text = readRawValue(cfg, section, f.info.key);
		try
		{
			f.set(s, text);
		}
		catch (const std::invalid_argument& e)
		{
			std::string as_written = f.info.key;
			for (const auto& k : present)
				if (sameKey(k, f.info.key)) as_written = k;
			throw KeyError("[" + section + "] " + f.info.key + " = '" + text + "': " + e.what(), section, as_written);
		}
	}
}

template <class S>
std::string OptionsTable<S>::print(const S& s) const
{
	std::string out;
	for (const auto& f : fields_) out += f.info.key + " = " + f.print(s) + "\n";
	return out;
}

template <class S>
std::vector<std::string> OptionsTable<S>::keys() const
{
	std::vector<std::string> k;
	for (const auto& f : fields_) k.push_back(f.info.key);
	return k;
}

}  // namespace omnirange
