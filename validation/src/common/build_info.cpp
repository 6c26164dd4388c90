// The source tree's git revision, as the build recorded it (validation/cmake/git_revision.cmake,
// run on every build). gjk-validate runs no git and reads nothing of the source tree at run time.
#include "common/context.hpp"

#include "git_revision.hpp"

namespace gjkval
{

std::string gitRevision()
{
    return GJK2D_GIT_REVISION;
}

} // namespace gjkval
