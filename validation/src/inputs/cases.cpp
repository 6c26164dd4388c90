#include "inputs/cases.hpp"

#include <fmt/format.h>

#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>

namespace gjkval
{
namespace fs = std::filesystem;
namespace
{
using RJson = nlohmann::json; // reading: key order does not matter

const char* typeName(const RJson& j)
{
    switch (j.type())
    {
    case RJson::value_t::null:
        return "null";
    case RJson::value_t::object:
        return "an object";
    case RJson::value_t::array:
        return "an array";
    case RJson::value_t::string:
        return "a string";
    case RJson::value_t::boolean:
        return "a boolean";
    case RJson::value_t::number_integer:
    case RJson::value_t::number_unsigned:
    case RJson::value_t::number_float:
        return "a number";
    default:
        return "not a value";
    }
}

// A field error: thrown while reading one case, caught per case (the case is rejected).
struct FieldError
{
    std::string message;
};

[[noreturn]] void fieldError(std::string message)
{
    throw FieldError{std::move(message)};
}

// A number field. JSON has no NaN or infinity: the strings "nan", "inf", "-inf" (the report's own
// convention) are read as such so that they can be rejected with a precise message.
double readNumber(const RJson& j, const std::string& field)
{
    double v = 0;
    if (j.is_number())
        v = j.get<double>();
    else if (j.is_string())
    {
        std::string s = j.get<std::string>();
        for (auto& ch : s)
            ch = char(std::tolower(static_cast<unsigned char>(ch)));
        if (s == "nan" || s == "-nan" || s == "+nan")
            v = std::numeric_limits<double>::quiet_NaN();
        else if (s == "inf" || s == "+inf" || s == "infinity" || s == "+infinity")
            v = std::numeric_limits<double>::infinity();
        else if (s == "-inf" || s == "-infinity")
            v = -std::numeric_limits<double>::infinity();
        else
            fieldError(fmt::format("{} is a string, expected a number", field));
    }
    else
        fieldError(fmt::format("{} is {}, expected a number", field, typeName(j)));
    if (std::isnan(v))
        fieldError(fmt::format("{} is NaN", field));
    if (std::isinf(v))
        fieldError(fmt::format("{} is infinite", field));
    return v;
}

std::array<double, 2> readPair(const RJson& j, const std::string& field)
{
    if (!j.is_array())
        fieldError(fmt::format("{} is {}, expected an array [x, y]", field, typeName(j)));
    if (j.size() != 2)
        fieldError(fmt::format("{} has {} elements, expected 2", field, j.size()));
    return {readNumber(j[0], field + "[0]"), readNumber(j[1], field + "[1]")};
}

ShapeIn readShape(const RJson& c, const char* key)
{
    const std::string k = key;
    if (!c.contains(key))
        fieldError(fmt::format("missing field '{}'", k));
    const RJson& j = c[key];
    if (!j.is_object())
        fieldError(fmt::format("{} is {}, expected an object", k, typeName(j)));
    ShapeIn s;
    if (!j.contains("points"))
        fieldError(fmt::format("missing field '{}.points'", k));
    const RJson& pts = j["points"];
    if (!pts.is_array())
        fieldError(fmt::format("{}.points is {}, expected an array", k, typeName(pts)));
    if (pts.empty())
        fieldError(fmt::format("{}.points is empty", k));
    if (pts.size() > kMaxShapePoints)
        fieldError(
            fmt::format("{}.points has {} points, more than {}", k, pts.size(), kMaxShapePoints));
    s.points.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
        s.points.push_back(readPair(pts[i], fmt::format("{}.points[{}]", k, i)));
    if (j.contains("radius"))
    {
        s.radius = readNumber(j["radius"], k + ".radius");
        if (s.radius < 0)
            fieldError(fmt::format("{}.radius is negative ({})", k, s.radius));
    }
    if (j.contains("transform"))
    {
        const RJson& t = j["transform"];
        if (!t.is_object())
            fieldError(fmt::format("{}.transform is {}, expected an object", k, typeName(t)));
        if (t.contains("p"))
        {
            const auto p = readPair(t["p"], k + ".transform.p");
            s.px = p[0];
            s.py = p[1];
        }
        if (t.contains("q"))
        {
            const auto q = readPair(t["q"], k + ".transform.q");
            s.c = q[0];
            s.s = q[1];
            // Any finite (c, s) other than (0, 0) is a transform (x' = c x - s y + p scales by
            // sqrt(c^2 + s^2)): GJK and the exact side both apply it as given. A float engine's
            // (cos, sin) is a unit vector only to float rounding. (0, 0) maps the whole
            // shape to one point: not a transform.
            if (s.c == 0 && s.s == 0)
                fieldError(fmt::format("{}.transform.q is (0, 0): not a rotation", k));
        }
    }
    return s;
}


const char* fileTypeName(fs::file_type t)
{
    switch (t)
    {
    case fs::file_type::directory:
        return "a directory";
    case fs::file_type::character:
        return "a character device";
    case fs::file_type::block:
        return "a block device";
    case fs::file_type::socket:
        return "a socket";
    default:
        return "not a regular file";
    }
}

// The whole file, at most kMaxCaseFileBytes: a regular file is refused by its size before it is
// read, a pipe once it has delivered more (an endless stream costs the cap, not all memory).
// Devices (/dev/zero), directories and sockets are refused by their type.
InputError tooLarge(const std::string& path)
{
    return InputError(fmt::format("{}: larger than {} bytes, the limit for a case file",
                                  shownPath(path), kMaxCaseFileBytes));
}

// The type of a case file about to be read: a regular file (within kMaxCaseFileBytes) or a pipe.
fs::file_type openedType(const std::string& path)
{
    const std::string shown = shownPath(path);
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec)
        throw InputError(fmt::format("{}: cannot open the file: {}", shown, ec.message()));
    if (st.type() != fs::file_type::regular && st.type() != fs::file_type::fifo)
        throw InputError(fmt::format("{}: is {}, expected a case file (a regular file or a pipe)",
                                     shown, fileTypeName(st.type())));
    if (st.type() == fs::file_type::regular)
    {
        const auto size = fs::file_size(path, ec);
        if (!ec && size > kMaxCaseFileBytes)
            throw tooLarge(path);
    }
    return st.type();
}

std::string readFile(const std::string& path)
{
    const std::string shown = shownPath(path);
    std::error_code ec;
    std::string text;
    if (openedType(path) == fs::file_type::regular)
    {
        const auto size = fs::file_size(path, ec);
        if (!ec)
            text.reserve(size);
    }
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(fmt::format("{}: cannot open the file", shown));
    std::vector<char> buffer(std::size_t(1) << 16);
    while (in)
    {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        const auto got = std::size_t(in.gcount());
        if (text.size() + got > kMaxCaseFileBytes)
            throw tooLarge(path);
        text.append(buffer.data(), got);
    }
    if (in.bad())
        throw InputError(fmt::format("{}: read error", shown));
    return text;
}

bool bitsEqual(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

Json readJsonFile(const std::string& path, const std::string& who)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(
            fmt::format("{}: {}: cannot open: {}", who, shownPath(path), std::strerror(errno)));
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    try
    {
        return Json::parse(text);
    }
    catch (const Json::parse_error& e)
    {
        const auto [line, col] = lineColumn(text, e.byte == 0 ? 0 : e.byte - 1);
        throw InputError(fmt::format("{}: {}:{}:{}: not JSON", who, shownPath(path), line, col));
    }
}

namespace
{
bool isControl(std::string_view s)
{
    for (std::size_t i = 0; i < s.size();)
    {
        const std::size_t n = utf8SequenceLength(s, i);
        const unsigned c = static_cast<unsigned char>(s[i]);
        if (n == 0 || c < 0x20 || c == 0x7F ||
            (n == 2 && c == 0xC2 && static_cast<unsigned char>(s[i + 1]) < 0xA0))
            return true;
        i += n;
    }
    return false;
}

// One entry of "cases", from its JSON (at most kMaxCaseJsonValues values of it; `truncated` when
// the rest was not kept).
CaseEntry readCase(const RJson& c, std::size_t index, bool truncated, const std::string& base,
                   std::set<std::string>& names)
{
    CaseEntry e;
    e.label = fmt::format("{}#{}", base, index);
    try
    {
        const std::string tooLarge =
            fmt::format("the case has more than {} JSON values", kMaxCaseJsonValues);
        if (truncated && !(c.is_object() && c.contains("name")))
            fieldError(tooLarge);
        if (!c.is_object())
            fieldError(fmt::format("the case is {}, expected an object", typeName(c)));
        if (!c.contains("name"))
            fieldError("missing field 'name'");
        if (!c["name"].is_string() || c["name"].get_ref<const std::string&>().empty())
            fieldError("name is not a non-empty string");
        // The name is quoted in labels, reports and terminals and looked up by `explain`: short,
        // printable, and (as every JSON string nlohmann reads) valid UTF-8.
        const std::string& name = c["name"].get_ref<const std::string&>();
        e.label = fmt::format("{}#{} (case '{}')", base, index, excerpt(name));
        if (name.size() > kMaxCaseNameBytes)
            fieldError(
                fmt::format("name is {} bytes long, more than {}", name.size(), kMaxCaseNameBytes));
        if (!isValidUtf8(name) || isControl(name))
            fieldError("name contains a control character or is not valid UTF-8");
        if (!names.insert(name).second)
            fieldError(fmt::format("duplicate case name '{}'", excerpt(name)));
        e.c.name = name;
        if (truncated) // named when the name came before the cut
            fieldError(tooLarge);
        e.c.a = readShape(c, "a");
        e.c.b = readShape(c, "b");
    }
    catch (const FieldError& err)
    {
        e.rejected = err.message;
        if (e.c.name.empty())
            e.c.name = e.label;
    }
    return e;
}

// Where nlohmann's lexer is in the input: its SAX callbacks get no position, and the reader's own
// errors (depth, duplicate key, number) name line and column. The input is read once, as a
// stream: only the current and the previous line's starts, the last character, and where the
// last string opened are kept (every position a message names lies within them: a number or a key
// never spans lines).
struct ReadPosition
{
    std::size_t offset = 0;        // characters read
    std::size_t line = 1;          // of the next character
    std::size_t lineStart = 0;     // offset of the current line's first character
    std::size_t prevLineStart = 0; // ... and of the previous line's
    char last = 0;                 // the last character read
    bool inString = false, escaped = false;
    std::size_t stringStart = 0; // offset of the opening quote of the last string
    std::size_t lastMinus = std::size_t(-1); // offset of the last '-' outside strings

    void advance(char c)
    {
        if (inString)
        {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        }
        else if (c == '"')
            inString = true, stringStart = offset;
        else if (c == '-')
            lastMinus = offset;
        last = c;
        ++offset;
        if (c == '\n')
        {
            ++line;
            prevLineStart = lineStart;
            lineStart = offset;
        }
    }

    // Line and column (both from 1, columns in bytes) of a recent offset.
    std::pair<std::size_t, std::size_t> lineColumn(std::size_t at) const
    {
        if (at >= lineStart)
            return {line, at - lineStart + 1};
        if (at >= prevLineStart && line > 1)
            return {line - 1, at - prevLineStart + 1};
        return {line, 1}; // not reached: messages name recent positions
    }
};

// An input iterator over a stream buffer that records the position of what it has read.
struct TrackedIterator
{
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = char;

    std::streambuf* in = nullptr; // nullptr: the end
    ReadPosition* pos = nullptr;

    bool atEnd() const
    {
        return in == nullptr || in->sgetc() == std::char_traits<char>::eof();
    }
    reference operator*() const { return std::char_traits<char>::to_char_type(in->sgetc()); }
    TrackedIterator& operator++()
    {
        pos->advance(std::char_traits<char>::to_char_type(in->sbumpc()));
        return *this;
    }
    bool operator==(const TrackedIterator& o) const { return atEnd() == o.atEnd(); }
};

// A stream buffer over text in memory (parseCaseFile, pipes), without a copy.
struct MemoryBuffer : std::streambuf
{
    explicit MemoryBuffer(const std::string& text)
    {
        char* p = const_cast<char*>(text.data()); // read only: setg needs char*
        setg(p, p, p + text.size());
    }
};

class CaseFileHandler
{
  public:
    CaseFileHandler(const std::string& sourceName, const std::function<void(CaseEntry&&)>& consume)
        : shown_(shownPath(sourceName)), consume_(consume)
    {
        base_ = sourceName;
        if (const auto slash = base_.find_last_of('/'); slash != std::string::npos)
            base_ = base_.substr(slash + 1);
        base_ = excerpt(base_);
    }

    // Reads the whole input; returns the file's comments and number of entries.
    CaseFileSummary parse(std::streambuf& in)
    {
        TrackedIterator first{&in, &pos_}, last{nullptr, &pos_};
        if (!RJson::sax_parse(first, last, this))
            throw InputError(error_.empty() ? shown_ + ": invalid JSON" : error_);
        return finish();
    }

    // nlohmann's SAX interface.
    bool null() { return scalar(nullptr); }
    bool boolean(bool v) { return scalar(v); }
    bool number_integer(std::int64_t v)
    {
        // "-0" is read as the integer 0: keep its sign, as the writer's -0.0 does.
        if (v == 0 && literalStart(1) > 0 && pos_.lastMinus == literalStart(1) - 1)
            return scalar(-0.0);
        return scalar(v);
    }
    bool number_unsigned(std::uint64_t v) { return scalar(v); }
    bool number_float(double v, const std::string& literal)
    {
        // nlohmann refuses overflow itself (parse_error 406); underflow to 0 it passes silently.
        if (v == 0)
        {
            const std::string mantissa = literal.substr(0, literal.find_first_of("eE"));
            if (mantissa.find_first_of("123456789") != std::string::npos)
                return fail(literalStart(literal.size()),
                            fmt::format("number {} is not 0 but rounds to 0 in a double",
                                        excerpt(literal)));
        }
        return scalar(v);
    }
    bool string(std::string& v) { return scalar(std::move(v)); }
    bool binary(RJson::binary_t&) { return fail(offset(), "binary value"); } // not in JSON text
    bool start_object(std::size_t) { return open(RJson::object(), true); }
    bool start_array(std::size_t) { return open(RJson::array(), false); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(std::string& k)
    {
        Frame& f = frames_.back();
        if (!f.keys.insert(k).second)
            return fail(keyStart(), fmt::format("invalid JSON: duplicate key \"{}\"", excerpt(k)));
        f.key = std::move(k);
        return true;
    }
    bool parse_error(std::size_t position, const std::string& lastToken,
                     const nlohmann::detail::exception& ex)
    {
        if (ex.id == 406) // number overflow: position is just past the literal
            return fail(position - std::min(position, lastToken.size()),
                        fmt::format("number {} overflows a double", excerpt(lastToken)));
        // nlohmann's message quotes the last token whole (a 200 MB string): quote an excerpt.
        std::string what = ex.what();
        if (const auto at = what.find("] "); at != std::string::npos)
            what = what.substr(at + 2);
        if (what.rfind("parse error", 0) == 0)
            if (const auto colon = what.find(": "); colon != std::string::npos)
                what = what.substr(colon + 2);
        // The rest of its message is its own fixed text.
        const std::string quoted = "; last read: '" + lastToken + "'";
        if (const auto at = what.find(quoted); at != std::string::npos)
            what.replace(at, quoted.size(), "; last read: '" + excerpt(lastToken) + "'");
        else
            what = excerpt(what, 300);
        // nlohmann's position is one past the offending character.
        return fail(position == 0 ? 0 : position - 1, "invalid JSON: " + what);
    }

  private:
    enum class Role
    {
        Kept,     // a container whose children are kept
        Dropped,  // checked, nothing kept
        Shallow,  // "comments": its children are kept, theirs not
        Cases,    // "cases": each child is one case, converted when complete
        TopLevel, // the top-level object: keeps format, comments and cases
    };
    struct Frame
    {
        RJson* node = nullptr; // nullptr when nothing is kept
        Role role = Role::Dropped;
        bool object = false;
        std::set<std::string> keys;
        std::string key; // the current key of an object
        std::size_t count = 0;
    };

    std::size_t offset() const { return pos_.offset; }

    // Byte offset where the literal of `length` bytes just read starts. The lexer reads one
    // character past a number unless the text ends; a number literal ends with a digit and is
    // never followed by one.
    std::size_t literalStart(std::size_t length) const
    {
        std::size_t end = offset();
        if (end > 0 && !std::isdigit(static_cast<unsigned char>(pos_.last)))
            --end;
        return end - std::min(end, length);
    }

    // Byte offset of the opening quote of the key just read (the lexer stopped at its closing
    // quote).
    std::size_t keyStart() const { return pos_.stringStart; }

    bool fail(std::size_t at, const std::string& message)
    {
        const auto [line, column] = pos_.lineColumn(at);
        error_ = fmt::format("{}:{}:{}: {}", shown_, line, column, message);
        return false;
    }

    bool inCase() const { return frames_.size() >= 2 && frames_[1].role == Role::Cases; }

    // Puts a new value (a scalar or an empty container) where it belongs; returns where it was
    // kept and the role of a container's frame, or false on a refusal.
    bool place(RJson&& v, RJson*& kept, Role& role)
    {
        kept = nullptr;
        role = Role::Dropped;
        if (frames_.empty())
        {
            top_ = std::move(v); // anything but an object is refused by finish()
            if (top_.is_object())
                kept = &top_, role = Role::TopLevel;
            return true;
        }
        Frame& f = frames_.back();
        ++f.count;
        switch (f.role)
        {
        case Role::Dropped:
            return true;
        case Role::TopLevel:
            if (f.key == "format")
                top_[f.key] = std::move(v); // only a string is valid: a container stays empty
            else if (f.key == "comments")
            {
                const bool array = v.is_array();
                kept = &(top_[f.key] = std::move(v));
                role = array ? Role::Shallow : Role::Dropped;
            }
            else if (f.key == "cases")
            {
                role = v.is_array() ? Role::Cases : Role::Dropped;
                top_[f.key] = std::move(v);
            }
            return true;
        case Role::Shallow:
            if (f.count > kMaxComments)
                return fail(offset(), fmt::format("more than {} comments", kMaxComments));
            if (v.is_string() && v.get_ref<const std::string&>().size() > kMaxCommentBytes)
                return fail(offset(),
                            fmt::format("comments[{}] is {} bytes long, more than {}", f.count - 1,
                                        v.get_ref<const std::string&>().size(), kMaxCommentBytes));
            f.node->push_back(std::move(v));
            return true;
        case Role::Cases:
            if (f.count > kMaxCasesPerFile)
                return fail(offset(),
                            fmt::format("more than {} cases in one file", kMaxCasesPerFile));
            case_ = std::move(v);
            caseValues_ = 1;
            caseTruncated_ = false;
            kept = &case_, role = Role::Kept;
            return true;
        case Role::Kept:
            if (inCase() && (caseTruncated_ || ++caseValues_ > kMaxCaseJsonValues))
            {
                caseTruncated_ = true; // the case is rejected when complete
                return true;
            }
            if (f.object)
                kept = &((*f.node)[f.key] = std::move(v));
            else
            {
                f.node->push_back(std::move(v));
                kept = &f.node->back();
            }
            role = Role::Kept;
            return true;
        }
        return true;
    }

    template <class T> bool scalar(T&& v)
    {
        RJson* kept;
        Role role;
        if (!place(RJson(std::forward<T>(v)), kept, role))
            return false;
        afterValue();
        return true;
    }

    bool open(RJson&& empty, bool object)
    {
        if (frames_.size() >= kMaxJsonDepth)
            return fail(offset() - 1,
                        fmt::format("JSON nested deeper than {} levels", kMaxJsonDepth));
        RJson* kept;
        Role role;
        if (!place(std::move(empty), kept, role))
            return false;
        Frame f;
        f.node = kept;
        f.role = kept || role == Role::Cases ? role : Role::Dropped;
        f.object = object;
        frames_.push_back(std::move(f));
        return true;
    }

    bool close()
    {
        frames_.pop_back();
        afterValue();
        return true;
    }

    // A value is complete: when it is an entry of "cases", convert it.
    void afterValue()
    {
        if (frames_.size() == 2 && frames_[1].role == Role::Cases)
        {
            consume_(readCase(case_, entries_, caseTruncated_, base_, names_));
            ++entries_;
            case_ = RJson();
        }
    }

    CaseFileSummary finish()
    {
        if (!top_.is_object())
            throw InputError(
                fmt::format("{}: not a {} file: the top level is {}, expected an object", shown_,
                            kCaseFormat, typeName(top_)));
        if (!top_.contains("format"))
            throw InputError(
                fmt::format("{}: not a {} file: no \"format\" field", shown_, kCaseFormat));
        const RJson& format = top_["format"];
        if (!format.is_string())
            throw InputError(fmt::format("{}: not a {} file: format is {}", shown_, kCaseFormat,
                                         typeName(format)));
        if (format.get_ref<const std::string&>() != kCaseFormat)
            throw InputError(fmt::format("{}: not a {} file: format is \"{}\"", shown_, kCaseFormat,
                                         excerpt(format.get_ref<const std::string&>())));
        if (!top_.contains("cases") || !top_["cases"].is_array())
            throw InputError(fmt::format("{}: \"cases\" is missing or not an array", shown_));
        CaseFileSummary file;
        file.entries = entries_;
        if (top_.contains("comments"))
        {
            const RJson& cm = top_["comments"];
            if (!cm.is_array())
                throw InputError(
                    fmt::format("{}: \"comments\" is not an array of strings", shown_));
            for (const auto& s : cm)
            {
                if (!s.is_string())
                    throw InputError(
                        fmt::format("{}: \"comments\" is not an array of strings", shown_));
                file.comments.push_back(s.get<std::string>());
            }
        }
        return file;
    }

    std::string shown_; // the file as messages name it
    std::string base_;  // its last component as labels name it
    const std::function<void(CaseEntry&&)>& consume_;
    ReadPosition pos_; // TrackedIterator's record
    std::string error_;
    std::vector<Frame> frames_;
    RJson top_;
    RJson case_;
    std::size_t caseValues_ = 0;
    bool caseTruncated_ = false;
    std::size_t entries_ = 0;
    std::set<std::string> names_;
};

CaseFile collect(std::streambuf& in, const std::string& sourceName)
{
    CaseFile file;
    file.path = sourceName;
    const std::function<void(CaseEntry&&)> keep = [&](CaseEntry&& e)
    { file.entries.push_back(std::move(e)); };
    file.comments = CaseFileHandler(sourceName, keep).parse(in).comments;
    return file;
}
} // namespace

CaseFile parseCaseFile(const std::string& text, const std::string& sourceName)
{
    MemoryBuffer in(text);
    return collect(in, sourceName);
}

CaseFile readCaseFile(const std::string& path)
{
    return parseCaseFile(readFile(path), path);
}

CaseFileSummary streamCaseFile(const std::string& path,
                               const std::function<void(CaseEntry&&)>& consume)
{
    if (openedType(path) == fs::file_type::fifo) // read once, whole: at most kMaxCaseFileBytes
    {
        const std::string text = readFile(path);
        MemoryBuffer in(text);
        return CaseFileHandler(path, consume).parse(in);
    }
    std::filebuf in;
    if (in.open(path, std::ios::in | std::ios::binary) == nullptr)
        throw InputError(fmt::format("{}: cannot open the file", shownPath(path)));
    return CaseFileHandler(path, consume).parse(in);
}

Json shapeToJson(const ShapeIn& s)
{
    Json pts = Json::array();
    for (const auto& p : s.points)
        pts.push_back(Json::array({p[0], p[1]}));
    Json j;
    j["points"] = std::move(pts);
    if (!bitsEqual(s.radius, 0.0))
        j["radius"] = s.radius;
    if (!bitsEqual(s.px, 0.0) || !bitsEqual(s.py, 0.0) || !bitsEqual(s.c, 1.0) ||
        !bitsEqual(s.s, 0.0))
        j["transform"] = {{"p", {s.px, s.py}}, {"q", {s.c, s.s}}};
    return j;
}

Json caseToJson(const Case& c)
{
    Json j;
    j["name"] = c.name;
    j["a"] = shapeToJson(c.a);
    j["b"] = shapeToJson(c.b);
    return j;
}

std::string caseFileText(const std::vector<std::string>& comments, const std::vector<Case>& cases)
{
    // nlohmann writes doubles in a form that reads back to the same bits (tests check it).
    std::string out = fmt::format("{{\"format\": \"{}\",\n", kCaseFormat);
    if (!comments.empty())
    {
        out += " \"comments\": [\n";
        for (std::size_t i = 0; i < comments.size(); ++i)
            out += "  " + Json(comments[i]).dump() + (i + 1 < comments.size() ? ",\n" : "\n");
        out += " ],\n";
    }
    out += " \"cases\": [\n";
    for (std::size_t i = 0; i < cases.size(); ++i)
        out += "  " + caseToJson(cases[i]).dump() + (i + 1 < cases.size() ? ",\n" : "\n");
    out += " ]}\n";
    return out;
}

void writeCaseFile(const std::string& path, const std::vector<std::string>& comments,
                   const std::vector<Case>& cases)
{
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw InputError(fmt::format("{}: cannot write the file", path));
    out << caseFileText(comments, cases);
    if (!out)
        throw InputError(fmt::format("{}: write failed", path));
}

double roundToFloat(double v)
{
    return double(float(v));
}

ShapeIn roundedToFloat(const ShapeIn& s)
{
    const auto r = roundToFloat;
    ShapeIn o = s;
    for (auto& p : o.points)
        p = {r(p[0]), r(p[1])};
    o.radius = r(s.radius);
    o.px = r(s.px);
    o.py = r(s.py);
    o.c = r(s.c);
    o.s = r(s.s);
    return o;
}

exact::Shape toExact(const ShapeIn& in, bool roundToFloat)
{
    const ShapeIn s = roundToFloat ? roundedToFloat(in) : in;
    exact::Shape e;
    e.points.reserve(s.points.size());
    for (const auto& p : s.points)
        e.points.push_back({p[0], p[1]});
    e.radius = s.radius;
    e.px = s.px;
    e.py = s.py;
    e.c = s.c;
    e.s = s.s;
    return e;
}

bool representableInFloat(const Case& c)
{
    auto ok = [](double v) { return std::isfinite(float(v)); };
    for (const ShapeIn* s : {&c.a, &c.b})
    {
        for (const auto& p : s->points)
            if (!ok(p[0]) || !ok(p[1]))
                return false;
        if (!ok(s->radius) || !ok(s->px) || !ok(s->py) || !ok(s->c) || !ok(s->s))
            return false;
        // A rotation that underflows to (0, 0) in float is no transform (cases.cpp rejects it).
        if (float(s->c) == 0 && float(s->s) == 0)
            return false;
    }
    return true;
}

} // namespace gjkval
