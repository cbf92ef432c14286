// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive's scope (docs/scope.md): traceable signals sampled by the drive at a divider of its fastest
// trace rate, either as a triggered capture (channel, level, edge, pre-trigger, single or normal) or
// continuously (roll mode, streamed). Every row carries the drive's sample number, so a reader sees
// any missing or repeated sample.
//
// ScopeRecorder is the trigger and ring-buffer logic on a stream of rows. The embedded simulated drive
// runs it inside the drive; a backend that only streams samples to the host (a LinuxCNC sampler on HAL
// pins, docs/scope.md "A backend that only streams") runs it on the host with the same code.

#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace axistune::device {

/// One traceable signal of a drive axis.
struct ScopeChannelInfo {
    std::string name;        ///< as in a capture ("motor_vel_rad_s")
    std::string unit;        ///< SI unit of its values ("rad/s")
    std::string description; ///< one line for a channel picker
};

/// What a drive's scope offers on an axis (Drive::scopeCapabilities).
struct ScopeCapabilities {
    std::vector<ScopeChannelInfo> channels;
    double fastestRateHz = 0.0;   ///< rate at divider 1 [Hz]
    int maxChannels = 0;          ///< channels in one capture or roll stream
    int maxDivider = 0;           ///< largest divider
    std::uint64_t maxValues = 0;  ///< channels × samples of one triggered capture
    std::uint64_t ringValues = 0; ///< channels × samples the roll-mode ring holds before the oldest is overwritten
};

enum class ScopeMode {
    Single, ///< one triggered capture, then the scope stops
    Normal, ///< a triggered capture, then it re-arms; the last complete capture can be read
    Roll,   ///< continuous: every sample into a ring, read out by sample number
};
enum class ScopeEdge { Rising, Falling, Either };

const char* scopeModeName(ScopeMode m);
const char* scopeEdgeName(ScopeEdge e);

struct ScopeRequest {
    std::string axis;
    std::vector<std::string> channels; ///< names from ScopeCapabilities::channels, in the order wanted
    int divider = 1;                   ///< sample every divider-th period of the fastest rate
    ScopeMode mode = ScopeMode::Single;
    // Triggered modes only.
    std::string triggerChannel; ///< one of `channels`
    double triggerLevel = 0.0;  ///< in the channel's unit
    ScopeEdge edge = ScopeEdge::Rising;
    double preTriggerPct = 0.0;      ///< share of the capture before the trigger row, 0..100
    std::uint64_t lengthSamples = 0; ///< rows per capture
};

enum class ScopeState {
    Idle,      ///< not armed (never, or stopped)
    Filling,   ///< armed, collecting the pre-trigger rows; a trigger is not yet accepted
    Waiting,   ///< armed, waiting for the trigger
    Triggered, ///< collecting the rows after the trigger
    Done,      ///< single: the capture is complete and the scope stopped
    Rolling,   ///< roll mode: streaming
};
const char* scopeStateName(ScopeState s);

struct ScopeStatus {
    ScopeState state = ScopeState::Idle;
    double rateHz = 0.0;            ///< rate of the armed scope [Hz]
    std::uint64_t nextSample = 0;   ///< sample number the next row will get (rows before it exist)
    std::uint64_t oldestSample = 0; ///< oldest sample number still in the ring
    std::uint64_t captures = 0;     ///< complete triggered captures since the scope was armed
    // The last complete capture (captures > 0).
    std::uint64_t captureFirstSample = 0;
    std::uint64_t captureTriggerSample = 0;
    std::uint64_t captureRows = 0;
};

/// Rows of the roll-mode ring: consecutive sample numbers from firstSample.
struct ScopeRows {
    std::uint64_t firstSample = 0;
    std::size_t rows = 0;
    std::vector<double> values; ///< rows × channels, row by row, channels in the request's order
};

/// A complete triggered capture, or rows gathered in roll mode (triggered = false).
struct ScopeCapture {
    std::vector<ScopeChannelInfo> channels; ///< in the request's order
    double rateHz = 0.0;
    bool triggered = true;
    std::uint64_t triggerSample = 0;          ///< sample number of the trigger row (triggered captures)
    std::uint64_t number = 0;                 ///< 1 for the first capture since arming, 2 for the next (normal mode)
    std::vector<std::uint64_t> samples;       ///< the drive's sample number of every row
    std::vector<std::vector<double>> columns; ///< one per channel, as long as `samples`
    std::size_t rows() const { return samples.size(); }
    /// Row of the trigger sample; rows() when it is not in the capture.
    std::size_t triggerRow() const;
    /// Samples missing between the first and the last row (gaps in the sample numbers).
    std::uint64_t missingSamples() const;
};

/// The request resolved against the channel list.
struct ScopeSetup {
    std::vector<std::size_t> channels; ///< indices into ScopeCapabilities::channels, in the request's order
    int divider = 1;
    ScopeMode mode = ScopeMode::Single;
    std::size_t triggerColumn = 0; ///< index into `channels`
    double triggerLevel = 0.0;
    ScopeEdge edge = ScopeEdge::Rising;
    std::uint64_t length = 0;     ///< rows per capture
    std::uint64_t preSamples = 0; ///< rows before the trigger row
    double rateHz = 0.0;
};

/// Rows before the trigger row for a pre-trigger share: round(pct/100 · length), at most length − 1 (100 %
/// puts the trigger on the last row).
std::uint64_t scopePreTriggerSamples(double pct, std::uint64_t length);

/// Checks a request against what the drive offers; errors name the request field and the allowed values.
Result<ScopeSetup> checkScopeRequest(const ScopeRequest& request, const ScopeCapabilities& caps);

/// Trigger, pre-trigger and ring buffer on a stream of rows (see the file comment).
class ScopeRecorder {
public:
    /// Arms with a checked setup; the roll ring holds ringRows rows (triggered: one capture).
    void arm(const ScopeSetup& setup, std::uint64_t ringRows);
    void stop();
    bool armed() const { return m_state != ScopeState::Idle && m_state != ScopeState::Done; }
    const ScopeSetup& setup() const { return m_setup; }
    /// One row (the setup's channels, in its order) with the drive's sample number; rows come in order.
    void push(std::uint64_t sample, std::span<const double> row);
    ScopeStatus status() const;
    /// Roll mode: up to maxRows rows from sample `from` (from the oldest kept when `from` was overwritten:
    /// firstSample > from then tells how many were lost).
    ScopeRows rows(std::uint64_t from, std::size_t maxRows) const;
    /// The last complete capture (NotFound before the first).
    Result<ScopeCapture> capture() const;

private:
    void appendToRing(std::uint64_t sample, std::span<const double> row);
    void finishCapture();

    ScopeSetup m_setup;
    ScopeState m_state = ScopeState::Idle;
    std::size_t m_width = 0;
    std::uint64_t m_capacity = 0;
    std::vector<double> m_ring;   ///< m_capacity rows × m_width
    std::uint64_t m_oldest = 0;   ///< sample number of the oldest row kept
    std::uint64_t m_next = 0;     ///< sample number after the newest row
    std::uint64_t m_count = 0;    ///< rows kept
    std::uint64_t m_sinceArm = 0; ///< rows since (re-)arming
    bool m_havePrevious = false;
    double m_previous = 0.0;
    std::uint64_t m_trigger = 0;
    std::uint64_t m_remaining = 0; ///< rows still to take after the trigger
    std::uint64_t m_captures = 0;
    bool m_haveCapture = false;
    ScopeCapture m_capture;
};

/// A scope capture as a capture table for the scope CSV (core/io/ScopeCsv.h): column `sample` (the drive's
/// sample numbers), then the channels; metadata fs_Hz, axis, the mode, the trigger, missing_samples and
/// unit.CHANNEL for every channel. `extra` is added to the metadata (connection, divider …).
model::Capture scopeCaptureToTable(const ScopeCapture& capture, const std::string& axis,
                                   const model::Metadata& extra = {});

/// Appends roll-mode rows (channels in the capture's order) to a roll capture.
void appendScopeRows(ScopeCapture& capture, const ScopeRows& rows);

} // namespace axistune::device
