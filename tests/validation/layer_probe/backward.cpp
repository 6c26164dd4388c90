// A file of the inputs layer that includes the campaign layer's header: validation/CMakeLists.txt
// gives the inputs library no path to it, so this must not compile (CTest "validation: a backward
// include fails to build"). Built only by that test.
#include "campaign/campaign.hpp"
#include "inputs/cases.hpp"
