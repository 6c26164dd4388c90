// The processes gjk-validate starts (executable adapters, shared-library plugins' children) and
// the ones they start: none outlives the run (docs/plugin-abi.md, "Its process tree").
// Each child leads a process group of its own, which is ended with it; gjk-validate is the child
// subreaper of its descendants, so that one that left its group (setsid) comes back to it when its
// parent ends, and is ended at the end of the run (sweepInherited).
#pragma once

namespace gjkval
{

// How many children may be owned at once: one slot each, kept without a lock for the signal
// handler of containDescendants(). The runner holds one per adapter and per plugin server.
inline constexpr int kMaxOwnedChildren = 4096;

// For the program (gjk-validate's main), once, before any child starts: makes this process the
// child subreaper of its descendants (prctl PR_SET_CHILD_SUBREAPER), which sweepInherited() needs,
// and ends every owned child's group before SIGINT, SIGTERM or SIGHUP end this process (where
// those are at their defaults: a group of its own no longer gets the terminal's Ctrl-C). Not for
// a host process such as the Python interpreter: the attribute is the whole process's, and the
// sweep could not tell the host's own children from what the runner's left behind. A failure says
// so once on stderr; the run goes on, each child's group still ended with it.
void containDescendants();

// In a child just forked, first: a process group of its own (setpgid), and none of the parent's
// children owned (they are its siblings).
void inForkedChild();

// In the parent, just after fork: the child `pid` in its own group (setpgid here too, as the
// child may not have run yet) and owned until disownChild(). A child that cannot have its own
// group (said once on stderr) is owned all the same; its group is then this process's and is
// never signalled. Throws std::logic_error when kMaxOwnedChildren are owned already.
void ownChild(int pid);

// SIGKILL to the owned child's group: the child, if it still runs, and whatever it left in the
// group. Call it before the child is reaped (a zombie still holds its PID, which names the group).
// False, and nothing sent, for a process this one does not own (a forked child's copy of its
// parent's state).
bool killChildGroup(int pid);

// Once its group is ended, before the child is reaped: no longer owned (nor signalled again).
void disownChild(int pid);

// Whether `pid` has exited, without reaping it (waitid WNOWAIT): `wait` blocks until it has. True
// for a process that is not this one's child (nothing to wait for).
bool childExited(int pid, bool wait);

// At the end of the run, when no other thread starts processes: SIGKILL to every child of this
// process that it does not own (orphans of its descendants, inherited as their subreaper), each
// reaped, until none is left. Nothing unless containDescendants() made this process a subreaper.
void sweepInherited();

} // namespace gjkval
