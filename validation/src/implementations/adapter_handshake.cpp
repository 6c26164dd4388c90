// The executable-adapter protocol's handshake (versions 1 and 2, docs/plugin-abi.md,
// "Executable adapters"): the host's version line, then the adapter's library, implementation,
// contract, prepared and input lines, each checked, to its `ready`.
#include "implementations/adapter_wire.hpp"

namespace gjkval::adapterwire
{
namespace
{
using namespace adapterio;

// ---- The handshake ----

bool validName(const std::string& s)
{
    if (s.empty() || s.size() > 64)
        return false;
    return std::all_of(s.begin(), s.end(),
                       [](char c)
                       {
                           return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                                  (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '+' ||
                                  c == '-';
                       });
}

// One `implementation` line, checked; AdapterFailure says what is wrong.
AdapterImplementation implementationLine(const std::string& line,
                                         const std::vector<AdapterImplementation>& before)
{
    const std::vector<std::string> t = tokens(line);
    if (t.size() < 5)
        throw AdapterFailure(
            fmt::format("bad description: {} has fewer than 5 fields", quoted80(line)));
    AdapterImplementation im;
    im.name = t[1];
    if (!validName(im.name))
        throw AdapterFailure(
            fmt::format("bad description: name '{}' is not 1 to 64 characters of [A-Za-z0-9._+-]",
                        im.name.substr(0, 80)));
    for (const auto& b : before)
        if (b.name == im.name)
            throw AdapterFailure(
                fmt::format("bad description: the name '{}' is taken (given twice)", im.name));
    if (t[2] != "float" && t[2] != "double")
        throw AdapterFailure(fmt::format(
            "bad description: implementation {}: scalar '{}' is neither float nor double", im.name,
            t[2].substr(0, 80)));
    im.scalar = t[2] == "float" ? Scalar::Float : Scalar::Double;
    if (t[3] != "radius" && t[3] != "no-radius")
        throw AdapterFailure(
            fmt::format("bad description: implementation {}: '{}' is neither radius nor no-radius",
                        im.name, t[3].substr(0, 80)));
    im.radius = t[3] == "radius";
    long long maxVertices = 0;
    if (!parseInteger(t[4], 0, INT32_MAX, maxVertices))
        throw AdapterFailure(fmt::format(
            "bad description: implementation {}: max_vertices '{}' is not an integer >= 0", im.name,
            t[4].substr(0, 80)));
    im.maxVertices = int(maxVertices);
    im.description = restAfter(line, 5);
    return im;
}

// The first line: `gjk2d-adapter 1` or `gjk2d-adapter 2`; the version.
int versionLine(const std::string& line)
{
    const std::vector<std::string> t = tokens(line);
    if (t.size() != 2 || t[0] != "gjk2d-adapter")
        throw AdapterFailure(
            fmt::format("bad description: the first line is {}, expected 'gjk2d-adapter {}'",
                        quoted80(line), kAdapterProtocolVersion));
    for (int v = kAdapterProtocolMinVersion; v <= kAdapterProtocolVersion; ++v)
        if (t[1] == std::to_string(v))
            return v;
    throw AdapterFailure(fmt::format(
        "executable adapter speaks protocol version {}, this gjk-validate speaks {} to {}",
        t[1].substr(0, 20), kAdapterProtocolMinVersion, kAdapterProtocolVersion));
}

// A tolerance token: a number >= 0, or `none`.
bool toleranceToken(const std::string& t, double& x)
{
    if (t == "none")
    {
        x = -1;
        return true;
    }
    return parseNumber(t, x) && std::isfinite(x) && x >= 0;
}

// One `contract NAME CLAUSE ...` line (version 2), into the implementation NAME declared before:
//   contract NAME overlap common-point|zero|midpoint|penetration|perimeter SOURCE...
//   contract NAME tolerance ABS|none REL|none SOURCE...
//   contract NAME margin M SOURCE...
//   contract NAME depth ABS|none REL|none SOURCE...   (the depth clause, for overlap penetration)
// SOURCE: where the library says so (file:line or its documentation, and its version); "" for a
// clause it does not state.
void contractLine(const std::string& line, std::vector<AdapterImplementation>& impls)
{
    const std::vector<std::string> t = tokens(line);
    auto bad = [&](const std::string& why)
    { return AdapterFailure(fmt::format("bad description: {}: {}", quoted80(line), why)); };
    if (t.size() < 4)
        throw bad("a contract line is `contract NAME overlap|tolerance|margin|depth ...`");
    auto it = std::find_if(impls.begin(), impls.end(),
                           [&](const AdapterImplementation& a) { return a.name == t[1]; });
    if (it == impls.end())
        throw bad("no implementation of that name before it");
    Contract& c = it->contract;
    c.own = false;
    if (t[2] == "overlap")
    {
        if (!parseOverlap(t[3], c.overlap))
            throw bad(
                "the overlap is none of common-point, zero, midpoint, penetration, perimeter");
        c.overlapSource = restAfter(line, 4);
    }
    else if (t[2] == "tolerance")
    {
        if (t.size() < 5 || !toleranceToken(t[3], c.absTolerance) ||
            !toleranceToken(t[4], c.relTolerance))
            throw bad("a tolerance is `tolerance ABS REL SOURCE...`, each a number >= 0 or none");
        c.toleranceSource = restAfter(line, 5);
    }
    else if (t[2] == "margin")
    {
        if (!parseNumber(t[3], c.margin) || !std::isfinite(c.margin) || c.margin < 0)
            throw bad("the margin is not a finite number >= 0");
        c.marginSource = restAfter(line, 4);
    }
    else if (t[2] == "depth")
    {
        if (t.size() < 5 || !toleranceToken(t[3], c.depthAbsTolerance) ||
            !toleranceToken(t[4], c.depthRelTolerance))
            throw bad("a depth tolerance is `depth ABS REL SOURCE...`, each a number >= 0 or none");
        c.depthSource = restAfter(line, 5);
    }
    else
        throw bad("the clause is none of overlap, tolerance, margin, depth");
}

// The contracts as a whole, once every line is read (a depth line may come before its overlap
// line): checkContract's refusals, e.g. a depth tolerance on an overlap that answers no depth.
void checkContracts(const std::vector<AdapterImplementation>& impls)
{
    for (const AdapterImplementation& a : impls)
    {
        const std::string problem = checkContract(a.contract);
        if (!problem.empty())
            throw AdapterFailure(
                fmt::format("bad description: implementation {}: {}", a.name, problem));
    }
}

// One `prepared NAME shape|case` line (version 2), for the implementation NAME declared before:
// the adapter builds a `time` request's shapes once, before its timed loop, in their own frame
// (`shape`: the transforms applied per query, as the library takes them) or with the case's world
// points baked in (`case`), and answers `timed ID NS PREPARE_NS`.
void preparedLine(const std::string& line, int version, std::vector<AdapterImplementation>& impls)
{
    const std::vector<std::string> t = tokens(line);
    auto bad = [&](const std::string& why)
    { return AdapterFailure(fmt::format("bad description: {}: {}", quoted80(line), why)); };
    if (version < 2)
        throw bad("a prepared line needs protocol version 2 (the adapter answered "
                  "'gjk2d-adapter 1')");
    if (t.size() != 3)
        throw bad("a prepared line is `prepared NAME shape|case`");
    auto it = std::find_if(impls.begin(), impls.end(),
                           [&](const AdapterImplementation& a) { return a.name == t[1]; });
    if (it == impls.end())
        throw bad("no implementation of that name before it");
    if (it->preparation != Preparation::InCall)
        throw bad("a second prepared line for that implementation");
    if (t[2] == "shape")
        it->preparation = Preparation::Shape;
    else if (t[2] == "case")
        it->preparation = Preparation::Case;
    else
        throw bad(fmt::format("the scope '{}' is neither shape nor case", t[2].substr(0, 80)));
}

// One `input NAME world SOURCE...` line (version 2), for the implementation NAME declared before:
// the library cannot take the case's transform exactly, so the host sends that implementation every
// case as its world case (inputs/geometry.hpp, worldCase) and judges it on that. SOURCE: why (the
// library's file:line).
void inputLine(const std::string& line, int version, std::vector<AdapterImplementation>& impls)
{
    const std::vector<std::string> t = tokens(line);
    auto bad = [&](const std::string& why)
    { return AdapterFailure(fmt::format("bad description: {}: {}", quoted80(line), why)); };
    if (version < 2)
        throw bad("an input line needs protocol version 2 (the adapter answered "
                  "'gjk2d-adapter 1')");
    if (t.size() < 3)
        throw bad("an input line is `input NAME world SOURCE...`");
    auto it = std::find_if(impls.begin(), impls.end(),
                           [&](const AdapterImplementation& a) { return a.name == t[1]; });
    if (it == impls.end())
        throw bad("no implementation of that name before it");
    if (it->contract.input != InputForm::Case)
        throw bad("a second input line for that implementation");
    if (t[2] != "world")
        throw bad(fmt::format("the input form '{}' is not world", t[2].substr(0, 80)));
    it->contract.input = InputForm::World; // beside its contract lines, own or declared
    it->contract.inputSource = restAfter(line, 3);
}

// Why the handshake stopped short: the adapter's exit, or the limit.
[[noreturn]] void handshakeCut(Process& p, Io io, double limit)
{
    if (io == Io::Timeout)
    {
        reap(p, 0);
        throw AdapterFailure(fmt::format("no 'ready' within {} s of the handshake", limit));
    }
    const std::string how = reap(p, kAdapterCloseSeconds);
    throw AdapterFailure(fmt::format("executable adapter exited during the handshake ({})", how));
}

} // namespace

AdapterDescription handshake(Process& p, double limit)
{
    const auto deadline = deadlineIn(limit);
    Io io = writeText(p, fmt::format("gjk2d-adapter {}\n", kAdapterProtocolMinVersion), deadline);
    std::string line;
    if (io != Io::Ok || (io = readLine(p, line, deadline)) != Io::Ok)
        handshakeCut(p, io, limit);
    AdapterDescription d;
    d.version = versionLine(line);
    bool haveLibrary = false;
    for (;;)
    {
        if ((io = readLine(p, line, deadline)) != Io::Ok)
            handshakeCut(p, io, limit);
        const std::vector<std::string> t = tokens(line);
        if (t.empty())
            continue; // spaces only: an empty line
        if (t[0] == "ready" && t.size() == 1)
            break;
        if (t[0] == "library" && !haveLibrary)
        {
            d.library = restAfter(line, 1);
            haveLibrary = true;
        }
        else if (t[0] == "implementation" && d.implementations.size() < 64)
            d.implementations.push_back(implementationLine(line, d.implementations));
        else if (t[0] == "contract" && d.version >= 2)
            contractLine(line, d.implementations);
        else if (t[0] == "prepared")
            preparedLine(line, d.version, d.implementations);
        else if (t[0] == "input")
            inputLine(line, d.version, d.implementations);
        else
            throw AdapterFailure(fmt::format(
                "bad description: unexpected line {} (a second library, a 65th implementation, "
                "or an unknown word)",
                quoted80(line)));
    }
    if (!haveLibrary)
        throw AdapterFailure("bad description: no 'library' line before 'ready'");
    if (d.implementations.empty())
        throw AdapterFailure("bad description: no 'implementation' line before 'ready'");
    checkContracts(d.implementations);
    return d;
}

} // namespace gjkval::adapterwire
