// Reading gjk-cases/1 files: the file checked and read within the reader's limits, its JSON
// streamed through nlohmann's SAX interface, each case handed to readCase (case_fields.hpp) when
// complete.
#include "inputs/case_binary.hpp"
#include "inputs/case_fields.hpp"
#include "inputs/cases.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <set>

namespace gjkval
{
namespace fs = std::filesystem;
namespace
{
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
    std::size_t stringStart = 0;             // offset of the opening quote of the last string
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

    bool atEnd() const { return in == nullptr || in->sgetc() == std::char_traits<char>::eof(); }
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
            return placeTopLevel(std::move(v), kept, role);
        Frame& f = frames_.back();
        ++f.count;
        switch (f.role)
        {
        case Role::Dropped:
            return true;
        case Role::TopLevel:
            return placeField(f, std::move(v), kept, role);
        case Role::Shallow:
            return placeComment(f, std::move(v));
        case Role::Cases:
            return startCase(f, std::move(v), kept, role);
        case Role::Kept:
            return placeKept(f, std::move(v), kept, role);
        }
        return true;
    }

    // The top-level value: anything but an object is refused by finish().
    bool placeTopLevel(RJson&& v, RJson*& kept, Role& role)
    {
        top_ = std::move(v);
        if (top_.is_object())
            kept = &top_, role = Role::TopLevel;
        return true;
    }

    // A field of the top-level object: "format", "comments" and "cases" are kept, others dropped.
    bool placeField(const Frame& f, RJson&& v, RJson*& kept, Role& role)
    {
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
    }

    // An entry of "comments": at most kMaxComments of them, each at most kMaxCommentBytes.
    bool placeComment(const Frame& f, RJson&& v)
    {
        if (f.count > kMaxComments)
            return fail(offset(), fmt::format("more than {} comments", kMaxComments));
        if (v.is_string() && v.get_ref<const std::string&>().size() > kMaxCommentBytes)
            return fail(offset(),
                        fmt::format("comments[{}] is {} bytes long, more than {}", f.count - 1,
                                    v.get_ref<const std::string&>().size(), kMaxCommentBytes));
        f.node->push_back(std::move(v));
        return true;
    }

    // An entry of "cases" begins: kept apart until complete (afterValue), at most
    // kMaxCasesPerFile of them.
    bool startCase(const Frame& f, RJson&& v, RJson*& kept, Role& role)
    {
        if (f.count > kMaxCasesPerFile)
            return fail(offset(), fmt::format("more than {} cases in one file", kMaxCasesPerFile));
        case_ = std::move(v);
        caseValues_ = 1;
        caseTruncated_ = false;
        kept = &case_, role = Role::Kept;
        return true;
    }

    // A value inside a kept container. Within a case, at most kMaxCaseJsonValues values are kept;
    // the rest are dropped and the case is rejected when complete.
    bool placeKept(const Frame& f, RJson&& v, RJson*& kept, Role& role)
    {
        if (inCase() && (caseTruncated_ || ++caseValues_ > kMaxCaseJsonValues))
        {
            caseTruncated_ = true;
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
    const std::function<void(CaseEntry &&)> keep = [&](CaseEntry&& e)
    { file.entries.push_back(std::move(e)); };
    file.comments = CaseFileHandler(sourceName, keep).parse(in).comments;
    return file;
}
} // namespace

CaseFile parseCaseFile(const std::string& text, const std::string& sourceName)
{
    if (!text.empty() && isBinaryCaseFileStart(static_cast<unsigned char>(text[0])))
        return parseBinaryCaseFile(text, sourceName); // the binary form: case_binary.hpp
    MemoryBuffer in(text);
    return collect(in, sourceName);
}

CaseFile readCaseFile(const std::string& path)
{
    if (isBinaryCaseFile(path)) // recognised by its first byte: case_binary.hpp
        return readBinaryCaseFile(path);
    return parseCaseFile(readFile(path), path);
}

CaseFileSummary streamCaseFile(const std::string& path,
                               const std::function<void(CaseEntry&&)>& consume)
{
    if (isBinaryCaseFile(path)) // recognised by its first byte: case_binary.hpp
        return streamBinaryCaseFile(path, consume);
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

} // namespace gjkval
