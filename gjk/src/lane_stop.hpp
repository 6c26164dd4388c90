// The two stop values of a lane that are not a StopReason (LaneState::stop, batch_lanes.hpp): the
// lane still runs, or it leaves the lanes for the scalar query. Negative, so that they never meet a
// StopReason's value. Their one home: batch_lanes.hpp (which runs the lanes, once per instruction
// set) and batch.cpp (which starts and ends them) both read them here.
#pragma once

namespace gjk::lanes
{

inline constexpr int kRunning = -1;
inline constexpr int kHandBack = -2;

} // namespace gjk::lanes
