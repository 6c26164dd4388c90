// Reading gjk-cases/1 files (a file in the binary form goes to case_binary.hpp instead): the file
// checked, its JSON streamed through nlohmann's SAX interface (every message, every position it
// names), each case handed to readCase (case_fields.hpp) when complete. A fast path reads most
// cases instead: where an entry of "cases" begins, the case's bytes are found, parsed with simdjson
// and checked field by field; a case that passes every check reaches the SAX parser as the one
// token `null`, and the case itself, already converted, goes to acceptCase. Anything else the fast
// path does not accept (an error of any kind, an unknown field, an escape in a string) it leaves to
// the SAX path, byte for byte: the messages stay those of the SAX path (docs/speed.md, "Case
// files").
#include "inputs/case_binary.hpp"
#include "inputs/case_fields.hpp"
#include "inputs/cases.hpp"

#include "common/output.hpp"

#include <fmt/format.h>
#include <simdjson.h>

#include <fcntl.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <unistd.h>

#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
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

// The type of a case file about to be read: a regular file or a pipe.
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
    return st.type();
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

// The characters of a case that the SAX parser does not see (the fast path read them): where
// its newlines are, so that positions after it stay right.
struct SkippedCase
{
    std::size_t bytes = 0;
    std::size_t newlines = 0;
    std::size_t lastNewline = 0, prevNewline = 0; // offsets within the case
};

void skip(ReadPosition& pos, const SkippedCase& c)
{
    const std::size_t base = pos.offset;
    if (c.newlines >= 2)
        pos.prevLineStart = base + c.prevNewline + 1;
    else if (c.newlines == 1)
        pos.prevLineStart = pos.lineStart;
    if (c.newlines >= 1)
        pos.lineStart = base + c.lastNewline + 1;
    pos.line += c.newlines;
    pos.offset += c.bytes;
    pos.last = '}';
    pos.inString = pos.escaped = false;
}

// Where the bytes come from: a file descriptor (a regular file or a pipe, read as it is parsed)
// or text in memory.
class ByteInput
{
  public:
    explicit ByteInput(int fd) : fd_(fd) {}
    explicit ByteInput(std::string_view text) : text_(text) {}
    ByteInput(const ByteInput&) = delete;
    ByteInput& operator=(const ByteInput&) = delete;
    ~ByteInput()
    {
        if (fd_ >= 0)
            ::close(fd_);
    }

    // Up to n bytes into p; 0 at the end. Throws InputError on a read error.
    std::size_t read(char* p, std::size_t n, const std::string& shown)
    {
        if (fd_ == kText)
        {
            const std::size_t got = std::min(n, text_.size());
            std::memcpy(p, text_.data(), got);
            text_.remove_prefix(got);
            return got;
        }
        for (;;)
        {
            const ssize_t got = ::read(fd_, p, n);
            if (got >= 0)
                return std::size_t(got);
            if (errno != EINTR)
                throw InputError(fmt::format("{}: read error", shown));
        }
    }

  private:
    static constexpr int kText = -2;
    int fd_ = kText;
    std::string_view text_;
};

// One case checked and converted by simdjson's On-Demand parser, or refused (false) for the SAX
// path to read: every field readCase (case_fields.cpp) accepts, nothing it rejects, no field it
// drops (those the SAX path still checks as JSON), and no number it refuses.
class FastCaseParser
{
  public:
    bool parse(const char* json, std::size_t length, Case& out)
    {
        namespace od = simdjson::ondemand;
        padded_.resize(length + simdjson::SIMDJSON_PADDING);
        std::memcpy(padded_.data(), json, length);
        od::document doc;
        od::object o;
        if (parser_.iterate(padded_.data(), length, padded_.size()).get(doc) ||
            doc.get_object().get(o))
            return false;
        values_ = 1;
        out = Case();
        unsigned seen = 0;
        for (auto field : o)
        {
            od::field f;
            std::string_view key;
            if (std::move(field).get(f) || f.unescaped_key().get(key))
                return false;
            od::value v = f.value();
            const unsigned bit = key == "name"      ? 1
                                 : key == "a"       ? 2
                                 : key == "b"       ? 4
                                 : key == "source"  ? 8
                                 : key == "comment" ? 16
                                                    : 0;
            if (bit == 0 || (seen & bit) != 0 || !count())
                return false;
            seen |= bit;
            const bool ok = bit == 1   ? name(v, out.name)
                            : bit == 2 ? shape(v, out.a)
                            : bit == 4 ? shape(v, out.b)
                            : bit == 8 ? text(v, out.source)
                                       : text(v, out.comment);
            if (!ok)
                return false;
        }
        return (seen & 7) == 7;
    }

  private:
    using Value = simdjson::ondemand::value;

    // Every JSON value of the case counted: at most kMaxCaseJsonValues (the SAX path rejects the
    // case beyond).
    bool count(std::size_t n = 1)
    {
        values_ += n;
        return values_ <= kMaxCaseJsonValues;
    }

    // A string without escapes or control characters (the scan before made sure), printable ASCII
    // as a name (readCase's isControl rejects DEL).
    static bool name(Value& v, std::string& out)
    {
        std::string_view s;
        if (v.get_string().get(s) || s.empty() || s.size() > kMaxCaseNameBytes ||
            s.find('\x7f') != std::string_view::npos)
            return false;
        out = s;
        return true;
    }

    static bool text(Value& v, std::string& out)
    {
        std::string_view s;
        if (v.get_string().get(s) || s.size() > kMaxCommentBytes)
            return false;
        out = s;
        return true;
    }

    // A number as nlohmann reads it: simdjson refuses overflow itself, and a literal that is not 0
    // but rounds to 0 is left to the SAX path, which refuses it.
    bool number(Value& v, double& out)
    {
        const std::string_view literal = v.raw_json_token();
        if (v.get_double().get(out))
            return false;
        if (out == 0)
        {
            const std::string_view mantissa = literal.substr(0, literal.find_first_of("eE"));
            if (mantissa.find_first_of("123456789") != std::string_view::npos)
                return false;
        }
        return true;
    }

    bool pair(Value& v, std::array<double, 2>& out)
    {
        simdjson::ondemand::array a;
        if (v.get_array().get(a))
            return false;
        std::size_t n = 0;
        for (auto element : a)
        {
            Value x;
            if (n == 2 || element.get(x) || !count() || !number(x, out[n]))
                return false;
            ++n;
        }
        return n == 2;
    }

    // The points are read into points_ (its capacity kept from case to case) and copied out at
    // their final size: one allocation a shape instead of one each time the vector grows.
    bool points(Value& v, std::vector<std::array<double, 2>>& out)
    {
        simdjson::ondemand::array a;
        if (v.get_array().get(a))
            return false;
        points_.clear();
        for (auto element : a)
        {
            Value p;
            if (points_.size() == kMaxShapePoints || element.get(p) || !count())
                return false;
            points_.emplace_back();
            if (!pair(p, points_.back()))
                return false;
        }
        out.assign(points_.begin(), points_.end());
        return !out.empty();
    }

    bool transform(Value& v, ShapeIn& s)
    {
        simdjson::ondemand::object o;
        if (v.get_object().get(o))
            return false;
        unsigned seen = 0;
        for (auto field : o)
        {
            simdjson::ondemand::field f;
            std::string_view key;
            if (std::move(field).get(f) || f.unescaped_key().get(key))
                return false;
            Value x = f.value();
            const unsigned bit = key == "p" ? 1 : key == "q" ? 2 : 0;
            if (bit == 0 || (seen & bit) != 0 || !count())
                return false;
            seen |= bit;
            std::array<double, 2> xy{};
            if (!pair(x, xy))
                return false;
            (bit == 1 ? s.px : s.c) = xy[0];
            (bit == 1 ? s.py : s.s) = xy[1];
        }
        return !(s.c == 0 && s.s == 0);
    }

    bool shape(Value& v, ShapeIn& s)
    {
        simdjson::ondemand::object o;
        if (v.get_object().get(o))
            return false;
        unsigned seen = 0;
        for (auto field : o)
        {
            simdjson::ondemand::field f;
            std::string_view key;
            if (std::move(field).get(f) || f.unescaped_key().get(key))
                return false;
            Value x = f.value();
            const unsigned bit = key == "points"      ? 1
                                 : key == "radius"    ? 2
                                 : key == "transform" ? 4
                                                      : 0;
            if (bit == 0 || (seen & bit) != 0 || !count())
                return false;
            seen |= bit;
            const bool ok = bit == 1   ? points(x, s.points)
                            : bit == 2 ? number(x, s.radius) && !(s.radius < 0)
                                       : transform(x, s);
            if (!ok)
                return false;
        }
        return (seen & 1) != 0;
    }

    simdjson::ondemand::parser parser_;
    std::vector<char> padded_;
    std::size_t values_ = 0;
    std::vector<std::array<double, 2>> points_;
};

// The input as the SAX parser reads it, one character at a time, with its position recorded; and
// the fast path. Where the handler expects an entry of "cases" (expectCase) and the next
// character after white space (and the comma between entries) opens an object, the case is
// scanned to its end and given to FastCaseParser. When it accepts the case, the SAX parser reads
// a placeholder in its place, and the handler takes the case when the placeholder ends
// (takeFastCase). The placeholder is valid JSON ending as the case ends, from the case's last
// string or number on (`{"":{"":[[1]]}}` for a case ending `1]]}}`): nlohmann quotes the
// characters from there on as "last read" in a message about what follows the case. A refused
// case is read by the SAX parser as it is. Where a comma and another case the fast path accepts
// follow a case it accepted, the first is handed to the handler at once (`direct`) and the SAX
// parser never sees it: only the last case of such a run becomes a placeholder, so every message
// about what follows stays the same.
class CaseStream
{
  public:
    CaseStream(ByteInput& in, std::string shown, std::function<void(Case&&)> direct)
        : in_(in), shown_(std::move(shown)), direct_(std::move(direct))
    {
        buf_.resize(std::size_t(1) << 20);
    }

    ReadPosition pos;

    bool atEnd()
    {
        prepare();
        return !inPlaceholder() && begin_ == end_;
    }
    char current()
    {
        prepare();
        return inPlaceholder() ? placeholder_[placed_] : buf_[begin_];
    }
    void next()
    {
        if (inPlaceholder())
        {
            if (++placed_ == placeholder_.size())
            {
                begin_ += skipped_.bytes;
                skip(pos, skipped_);
                delta_ += skipped_.bytes - placeholder_.size();
                fastReady_ = true;
            }
            return;
        }
        const char c = buf_[begin_++];
        pos.advance(c);
        if (c == ',' && expect_ == Expect::Comma)
            expect_ = Expect::Case;
        else if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
            expect_ = Expect::Nothing;
    }

    // What comes next in "cases": an entry (after its '['), or a comma and an entry (after one).
    void expectCase(bool first) { expect_ = first ? Expect::Case : Expect::Comma; }
    bool inPlaceholder() const { return placed_ < placeholder_.size(); }
    // True, once, right after the parser read the last character of a placeholder.
    bool takeFastCase(Case& c)
    {
        if (!fastReady_)
            return false;
        fastReady_ = false;
        c = std::move(fast_);
        return true;
    }
    // The offset in the input of the parser's offset `read` (placeholders count as their case).
    std::size_t inputOffset(std::size_t read) const { return read + delta_; }

  private:
    // The largest case the fast path reads at once; a larger one goes to the SAX path, which
    // bounds it by kMaxCaseJsonValues.
    static constexpr std::size_t kMaxFastCaseBytes = std::size_t(16) << 20;
    enum class Expect
    {
        Nothing,
        Comma,
        Case
    };

    void prepare()
    {
        if (inPlaceholder() || (begin_ == end_ && !fill(0)) || expect_ != Expect::Case ||
            buf_[begin_] != '{')
            return;
        expect_ = Expect::Nothing;
        if (!scan(0, true) || !parser_.parse(buf_.data() + begin_, skipped_.bytes, fast_))
            return;
        while (nextFastCase())
        {
        }
        makePlaceholder();
    }

    // With the case at begin_ read (skipped_, fast_): when white space, a comma, white space and
    // another case the fast path reads follow it, all in the buffer already, hands the first case
    // to the handler, passes it and what follows it up to the second, and returns true with the
    // second read in its place. Otherwise leaves everything as it was. Nothing more is read from
    // the input here: a case that arrived is handed on before the next one does (a pipe).
    bool nextFastCase()
    {
        const auto white = [&](std::size_t& i) // to the next other byte; false at the end
        {
            for (; begin_ + i < end_; ++i)
            {
                const char c = buf_[begin_ + i];
                if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
                    return true;
            }
            return false;
        };
        std::size_t from = skipped_.bytes;
        if (!white(from) || buf_[begin_ + from] != ',')
            return false;
        ++from;
        if (!white(from) || buf_[begin_ + from] != '{')
            return false;
        const SkippedCase first = skipped_;
        const std::size_t firstToken = lastToken_;
        if (!scan(from, false) ||
            !parser_.parse(buf_.data() + begin_ + from, skipped_.bytes, next_))
        {
            skipped_ = first;
            lastToken_ = firstToken;
            return false;
        }
        direct_(std::move(fast_));
        std::swap(fast_, next_);
        skip(pos, first);
        for (std::size_t i = first.bytes; i < from; ++i)
            pos.advance(buf_[begin_ + i]);
        begin_ += from;
        delta_ += from;
        return true;
    }

    // The placeholder of the case just scanned: openers for the closers after its last token,
    // then that token and what follows it.
    void makePlaceholder()
    {
        const std::string_view tail(buf_.data() + begin_ + lastToken_, skipped_.bytes - lastToken_);
        std::size_t after = 1; // past the token: a string (no escapes) or a number
        if (tail[0] == '"')
            after = tail.find('"', 1) + 1;
        else
            while (after < tail.size() && isNumberChar(tail[after]))
                ++after;
        placeholder_.clear();
        for (std::size_t i = tail.size(); i-- > after;)
            if (tail[i] == '}')
                placeholder_ += "{\"\":";
            else if (tail[i] == ']')
                placeholder_ += '[';
        placeholder_ += tail;
        placed_ = 0;
    }

    // Makes at least `want` bytes from begin_ available unless the input ends first; false when
    // none is left.
    bool fill(std::size_t want)
    {
        while (end_ - begin_ < std::max<std::size_t>(want, 1) && !eof_)
        {
            if (begin_ > 0)
            {
                std::memmove(buf_.data(), buf_.data() + begin_, end_ - begin_);
                end_ -= begin_;
                begin_ = 0;
            }
            if (end_ == buf_.size())
                buf_.resize(buf_.size() * 2);
            const std::size_t got = in_.read(buf_.data() + end_, buf_.size() - end_, shown_);
            eof_ = got == 0;
            end_ += got;
        }
        return end_ > begin_;
    }

    // Finds the end of the object at begin_ + from (skipped_, offsets from there), reading more
    // input as needed when `read`. False when the fast path leaves it to the SAX path: unbalanced
    // before the input ends, larger than kMaxFastCaseBytes, with a control character outside
    // JSON's white space, or with a string the scan does not vouch for (an escape, a control
    // character or a byte above 0x7F: simdjson and nlohmann might differ on it). Where the buffer
    // holds sixteen bytes, only the bytes marked in them (marks) are looked at; the last bytes of
    // the buffer one by one.
    bool scan(std::size_t from, bool read)
    {
        skipped_ = SkippedCase();
        ScanState st;
        std::size_t i = 0;
        for (;;)
        {
            if (begin_ + from + i + 16 <= end_)
            {
                const std::size_t block = begin_ + from + i;
                for (unsigned m = marks(block, st.inString); m != 0;)
                {
                    const unsigned k = unsigned(std::countr_zero(m));
                    const bool wasInString = st.inString;
                    if (!look(st, from, i + k, static_cast<unsigned char>(buf_[block + k])))
                        return st.done;
                    m &= m - 1;
                    if (st.inString != wasInString) // the rest of the block, for the new mode
                        m = marks(block, st.inString) & ~((2u << k) - 1);
                }
                i += 16;
                continue;
            }
            if (begin_ + from + i == end_ && (!read || i >= kMaxFastCaseBytes ||
                                              !fill(from + i + 1) || begin_ + from + i == end_))
                return false; // the case cannot be completed from here
            if (!look(st, from, i, static_cast<unsigned char>(buf_[begin_ + from + i])))
                return st.done;
            ++i;
        }
    }

    struct ScanState
    {
        std::size_t depth = 0;
        bool inString = false;
        bool done = false; // the case's end was found
    };

    // The scan's look at byte c, at offset `at` of the case at begin_ + from: false to stop (at
    // the case's end, st.done, or at a byte the fast path refuses).
    bool look(ScanState& st, std::size_t from, std::size_t at, unsigned char c)
    {
        if (st.inString)
        {
            if (c == '"')
                st.inString = false;
            return c == '"' || !(c == '\\' || c < 0x20 || c >= 0x80);
        }
        if (kOutside[c] == 0)
            return true;
        switch (c)
        {
        case '"':
            st.inString = true;
            return true;
        case '{':
        case '[':
            ++st.depth;
            return true;
        case '}':
        case ']':
            if (--st.depth != 0)
                return true;
            skipped_.bytes = at + 1;
            lastToken_ = lastTokenStart(from);
            st.done = true;
            return false;
        case '\n':
            ++skipped_.newlines;
            skipped_.prevNewline = skipped_.lastNewline;
            skipped_.lastNewline = at;
            return true;
        default: // not JSON white space, or above 0x7F
            return false;
        }
    }

    // Bytes the scan looks at outside strings: structure, newlines, and those it refuses (control
    // characters other than JSON's white space, bytes above 0x7F).
    static constexpr std::array<unsigned char, 256> kOutside = []
    {
        std::array<unsigned char, 256> t{};
        for (int c = 0; c < 256; ++c)
            t[std::size_t(c)] = (c < 0x20 && c != '\t' && c != '\r') || c >= 0x80 || c == '"' ||
                                c == '{' || c == '[' || c == '}' || c == ']';
        return t;
    }();

    // Bit k set for each byte buf_[at + k] of the sixteen from `at` that the scan must look at:
    // in a string, a quote, a backslash, a control character or a byte above 0x7F; outside, those
    // of kOutside, and tabs and carriage returns. With GCC's vector extensions.
    unsigned marks(std::size_t at, bool inString) const
    {
        using Bytes = unsigned char __attribute__((vector_size(16)));
        const Bytes quote = Bytes{} + '"', ctl = Bytes{} + 0x20, printable = Bytes{} + 0x60;
        Bytes v;
        std::memcpy(&v, buf_.data() + at, 16);
        // (c - 0x20) mod 256 >= 0x60: c below 0x20 or above 0x7F.
        auto marked = (v - ctl) >= printable;
        if (inString)
            marked |= v == quote || v == Bytes{} + '\\';
        else
        {
            // c | 0x20 maps '"' (and 0x02) to 0x22, '[' and '{' to 0x7B, ']' and '}' to 0x7D.
            const Bytes folded = v | ctl;
            marked |= folded == quote || folded == Bytes{} + '{' || folded == Bytes{} + '}';
        }
#if defined(__SSE2__) // one instruction (docs/speed.md, "Case files")
        return unsigned(_mm_movemask_epi8(__m128i(marked)));
#else
        std::uint64_t half[2];
        std::memcpy(half, &marked, 16);
        return byteMarks(half[0]) | byteMarks(half[1]) << 8;
#endif
    }

    // Bit j set when byte j (in memory order) of eight bytes, each 0x00 or 0xFF, is 0xFF: the
    // multiplication gathers each byte's top bit into the top byte.
    static unsigned byteMarks(std::uint64_t bytes)
    {
        if constexpr (std::endian::native == std::endian::big)
            bytes = __builtin_bswap64(bytes);
        return unsigned(((bytes & 0x8080808080808080u) * 0x0002040810204081u) >> 56);
    }

    static bool isNumberChar(char c)
    {
        return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
    }

    // Where the last string or number of the case just scanned begins: after it come only white
    // space and closing brackets (a case the fast path accepts has no true, false or null).
    std::size_t lastTokenStart(std::size_t from) const
    {
        const char* p = buf_.data() + begin_ + from;
        std::size_t i = skipped_.bytes;
        while (i > 0 && (p[i - 1] == '}' || p[i - 1] == ']' || p[i - 1] == ' ' ||
                         p[i - 1] == '\t' || p[i - 1] == '\r' || p[i - 1] == '\n'))
            --i;
        if (i == 0)
            return 0;
        if (p[i - 1] == '"')
        {
            --i;
            while (i > 0 && p[i - 1] != '"')
                --i;
            return i > 0 ? i - 1 : 0;
        }
        while (i > 0 && isNumberChar(p[i - 1]))
            --i;
        return i;
    }

    ByteInput& in_;
    std::string shown_;
    std::vector<char> buf_;
    std::size_t begin_ = 0, end_ = 0;
    bool eof_ = false;
    Expect expect_ = Expect::Nothing;
    std::string placeholder_;   // of the case the fast path read
    std::size_t placed_ = 0;    // characters of placeholder_ the parser read
    std::size_t lastToken_ = 0; // where the last string or number of the case scanned begins
    SkippedCase skipped_;
    bool fastReady_ = false;
    std::size_t delta_ = 0;
    FastCaseParser parser_;
    Case fast_;
    Case next_; // the case after fast_, while nextFastCase reads it
    std::function<void(Case&&)> direct_;
};

// An input iterator over a CaseStream, for nlohmann's sax_parse.
struct StreamIterator
{
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = char;

    CaseStream* in = nullptr; // nullptr: the end

    bool atEnd() const { return in == nullptr || in->atEnd(); }
    reference operator*() const { return in->current(); }
    StreamIterator& operator++()
    {
        in->next();
        return *this;
    }
    bool operator==(const StreamIterator& o) const { return atEnd() == o.atEnd(); }
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
    CaseFileSummary parse(ByteInput& input)
    {
        CaseStream in(input, shown_, [this](Case&& c) { takeCase(std::move(c)); });
        stream_ = &in;
        StreamIterator first{&in}, last{nullptr};
        if (!RJson::sax_parse(first, last, this))
            throw InputError(error_.empty() ? shown_ + ": invalid JSON" : error_);
        return finish();
    }

    // nlohmann's SAX interface.
    bool null() { return placeholder(0) || scalar(nullptr); }
    bool boolean(bool v) { return placeholder(0) || scalar(v); }
    bool number_integer(std::int64_t v)
    {
        if (placeholder(0))
            return true;
        // "-0" is read as the integer 0: keep its sign, as the writer's -0.0 does.
        if (v == 0 && literalStart(1) > 0 && stream_->pos.lastMinus == literalStart(1) - 1)
            return scalar(-0.0);
        return scalar(v);
    }
    bool number_unsigned(std::uint64_t v) { return placeholder(0) || scalar(v); }
    bool number_float(double v, const std::string& literal)
    {
        if (placeholder(0))
            return true;
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
    bool string(std::string& v) { return placeholder(0) || scalar(std::move(v)); }
    bool binary(RJson::binary_t&) { return fail(offset(), "binary value"); } // not in JSON text
    bool start_object(std::size_t) { return placeholder(1) || open(RJson::object(), true); }
    bool start_array(std::size_t) { return placeholder(1) || open(RJson::array(), false); }
    bool end_object() { return placeholder(-1) || close(); }
    bool end_array() { return placeholder(-1) || close(); }
    bool key(std::string& k)
    {
        if (placeholder(0))
            return true;
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
            return fail(stream_->inputOffset(position) - std::min(position, lastToken.size()),
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
        return fail(position == 0 ? 0 : stream_->inputOffset(position) - 1,
                    "invalid JSON: " + what);
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

    std::size_t offset() const { return stream_->pos.offset; }

    // The events of a placeholder (CaseStream) stand for a case the fast path read: when the
    // placeholder ends, that case is the next entry of "cases". `open`: +1 for the start of an
    // object or array, -1 for its end, 0 otherwise.
    bool placeholder(int open)
    {
        if (placeholderDepth_ == 0 && !(open > 0 && stream_->inPlaceholder()))
            return false;
        placeholderDepth_ += open;
        Case fast;
        if (placeholderDepth_ == 0 && stream_->takeFastCase(fast))
        {
            takeCase(std::move(fast));
            stream_->expectCase(false);
        }
        return true;
    }

    // The next entry of "cases", read by the fast path.
    void takeCase(Case&& c)
    {
        ++frames_.back().count; // as place() counts an entry
        consume_(acceptCase(std::move(c), entries_, base_, names_));
        ++entries_;
    }

    // Byte offset where the literal of `length` bytes just read starts. The lexer reads one
    // character past a number unless the text ends; a number literal ends with a digit and is
    // never followed by one.
    std::size_t literalStart(std::size_t length) const
    {
        std::size_t end = offset();
        if (end > 0 && !std::isdigit(static_cast<unsigned char>(stream_->pos.last)))
            --end;
        return end - std::min(end, length);
    }

    // Byte offset of the opening quote of the key just read (the lexer stopped at its closing
    // quote).
    std::size_t keyStart() const { return stream_->pos.stringStart; }

    bool fail(std::size_t at, const std::string& message)
    {
        const auto [line, column] = stream_->pos.lineColumn(at);
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
            return startCase(std::move(v), kept, role);
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

    // An entry of "cases" begins: kept apart until complete (afterValue).
    bool startCase(RJson&& v, RJson*& kept, Role& role)
    {
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
        if (frames_.back().role == Role::Cases)
            stream_->expectCase(true);
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
            stream_->expectCase(false);
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
    CaseStream* stream_ = nullptr; // the input being parsed, and its position
    int placeholderDepth_ = 0;     // objects and arrays of a placeholder open
    std::string error_;
    std::vector<Frame> frames_;
    RJson top_;
    RJson case_;
    std::size_t caseValues_ = 0;
    bool caseTruncated_ = false;
    std::size_t entries_ = 0;
    NameSet names_;
};

CaseFile collect(ByteInput& in, const std::string& sourceName)
{
    CaseFile file;
    file.path = sourceName;
    const std::function<void(CaseEntry &&)> keep = [&](CaseEntry&& e)
    { file.entries.push_back(std::move(e)); };
    file.comments = CaseFileHandler(sourceName, keep).parse(in).comments;
    return file;
}

// A case file opened for reading, its type checked first.
int openCaseFile(const std::string& path)
{
    openedType(path);
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw InputError(fmt::format("{}: cannot open the file", shownPath(path)));
    return fd;
}
} // namespace

CaseFile parseCaseFile(const std::string& text, const std::string& sourceName)
{
    if (!text.empty() && isBinaryCaseFileStart(static_cast<unsigned char>(text[0])))
        return parseBinaryCaseFile(text, sourceName); // the binary form: case_binary.hpp
    ByteInput in{std::string_view(text)};
    return collect(in, sourceName);
}

CaseFile readCaseFile(const std::string& path)
{
    if (isBinaryCaseFile(path)) // recognised by its first byte: case_binary.hpp
        return readBinaryCaseFile(path);
    ByteInput in(openCaseFile(path));
    return collect(in, path);
}

CaseFileSummary streamCaseFile(const std::string& path,
                               const std::function<void(CaseEntry&&)>& consume)
{
    return streamCaseFile(path, path, consume);
}

CaseFileSummary streamCaseFile(const std::string& readPath, const std::string& sourceName,
                               const std::function<void(CaseEntry&&)>& consume)
{
    if (isBinaryCaseFile(readPath)) // recognised by its first byte: case_binary.hpp
        return streamBinaryCaseFile(readPath, sourceName, consume);
    ByteInput in(openCaseFile(readPath));
    return CaseFileHandler(sourceName, consume).parse(in);
}

PipeCopy::PipeCopy(const std::string& pipe)
{
    const char* dir = std::getenv("TMPDIR");
    std::string name =
        std::string(dir != nullptr && *dir != 0 ? dir : "/tmp") + "/gjk-validate-pipe-XXXXXX";
    fd_ = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd_ < 0)
        throw OutputError(fmt::format("{}: cannot make a copy of the pipe {}: {}", excerpt(name),
                                      shownPath(pipe), std::strerror(errno)));
    ::unlink(name.c_str()); // unnamed from now on: gone with the descriptor
    path_ = fmt::format("/proc/self/fd/{}", fd_);
    try
    {
        ByteInput in(openCaseFile(pipe));
        std::vector<char> buffer(std::size_t(1) << 20);
        while (const std::size_t got = in.read(buffer.data(), buffer.size(), shownPath(pipe)))
            if (!writeAllBytes(fd_, buffer.data(), got))
                throw OutputError(fmt::format("{}: cannot copy the pipe {}: {}", excerpt(name),
                                              shownPath(pipe), std::strerror(errno)));
    }
    catch (...)
    {
        ::close(fd_);
        throw;
    }
}

PipeCopy::~PipeCopy()
{
    if (fd_ >= 0)
        ::close(fd_);
}

} // namespace gjkval
