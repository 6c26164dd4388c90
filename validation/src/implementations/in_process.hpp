// Variants whose answers come from a callback of this very process, registered at run time: the
// Python package's gjk2d.validate (python/src/py_validate.cpp, docs/python.md). The third kind of
// plugin (PluginKind::InProcess), judged and reported as the other two are, with one difference:
// it is never forked. A shared library's plugin answers in a forked child
// (implementations/plugins.cpp), so that a crash costs one case; a callback into a threaded runtime
// (JAX, a BLAS, the Python interpreter itself) would deadlock in a child that has only the forking
// thread. So a crash of the callback ends the process, a hang hangs it, and what it prints goes
// where the process's output goes (no plugin-*.log).
#pragma once

#include "implementations/plugins.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gjkval
{

// An in-process variant's callbacks: exactly one of them is set. Each fills the answers' distance,
// witness points and iterations (-1: not said); their status is set here (Ok).
// A callback throws for what it cannot answer: a std::exception's what() becomes the case's
// detail, the case counts as an error (PluginStatus::Error: a failure) and the campaign goes on.
// An exception of any other type (the Python layer's for KeyboardInterrupt) ends the campaign:
// it propagates out of answerContained() and the timing, and no report is written.
struct InProcessCalls
{
    // One case (one pair of shapes).
    std::function<void(const PreparedCase&, ExternalAnswer&)> perCase;
    // Many cases at once, for vectorised implementations: cases[i] into out[i] (out has the size
    // of cases). An exception counts for every case of the call.
    std::function<void(const std::vector<const PreparedCase*>& cases,
                       std::vector<ExternalAnswer>& out)>
        perBatch;
    bool toldFirstError = false; // the line on stderr for its first error is printed
};

// What the caller registers.
struct InProcessVariant
{
    std::string name;        // 1 to 64 characters of [A-Za-z0-9._+-], as a plugin's
    std::string source;      // what answers: the report's plugin path ("python:module.function")
    std::string library;     // what it wraps, name and version: context.plugins[].library
    std::string description; // optional
    Scalar scalar = Scalar::Double; // the cases in this type (a float variant's: float-rounded)
    bool acceptsRadius = true;      // false: cases with a radius are refused (skipped)
    int maxVertices = 0;            // > 0: cases with more points in a shape are refused
    InProcessCalls calls;
};

// Registers the variant in the plugin registry (implementations/plugins.cpp): a comparison variant,
// cold, held to gjk2d's reference bound in its scalar type as any plugin's; `run --variants` names
// it, `run --judge NAME` judges it. The same name again (a second campaign in one process) replaces
// the earlier registration in place, callbacks and judgement included (judged again only by a
// new --judge). Throws InputError, one line: an invalid name, no callback or both, a name that a
// gjk2d variant or a loaded plugin's implementation has.
const VariantInfo* registerInProcessVariant(InProcessVariant v);
// Drops the variant's callbacks and what they hold (a Python callable must be released while its
// interpreter runs); the variant stays registered but answers nothing: a campaign that runs it
// throws std::logic_error until it is registered again. No-op for an unknown name.
void releaseInProcessVariant(const std::string& name);

// answerContained()'s tasks of in-process variants (every task's variant has plugin->kind ==
// PluginKind::InProcess), in this thread: a per-case callback once per task, a batch callback
// once per variant with all of its tasks, in their order. Between the campaign's parallel phases:
// no worker thread runs.
void answerInProcess(const std::vector<PluginTask>& tasks);

} // namespace gjkval
