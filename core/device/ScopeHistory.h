// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The host side of a scope (docs/scope.md "The GUI scope"): a bounded history of roll-mode rows (a ring
// of a fixed number of rows per channel: memory stays bounded however long the scope rolls) and the
// way back from a stored or exported scope table to a ScopeCapture (store and scope CSV reopen).

#include "core/device/Scope.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <cstdint>
#include <vector>

namespace axistune::device {

/// The newest `capacityRows` rows of a roll stream, with their sample numbers. Allocated once at reset();
/// append() never grows it.
class ScopeHistory {
public:
    /// Empties the history for a stream of these channels (in the stream's order) at `rateHz`, keeping at
    /// most `capacityRows` rows (≥ 1).
    void reset(std::vector<ScopeChannelInfo> channels, double rateHz, std::size_t capacityRows);
    /// Appends rows read from the drive (channels in reset()'s order). Rows whose sample number does not
    /// follow the newest kept one are counted as lost (lostSamples()); a row older than the newest is
    /// ignored (counted in repeatedRows()).
    void append(const ScopeRows& rows);

    std::size_t capacity() const { return m_capacity; }
    std::size_t size() const { return m_count; }
    std::size_t channelCount() const { return m_channels.size(); }
    const std::vector<ScopeChannelInfo>& channels() const { return m_channels; }
    double rateHz() const { return m_rateHz; }
    /// Sample number of the newest row + 1 (0 when empty).
    std::uint64_t nextSample() const { return m_count == 0 ? 0 : m_newest + 1; }
    /// Samples missing between rows appended (gaps in the sample numbers since reset()).
    std::uint64_t lostSamples() const { return m_lost; }
    std::uint64_t repeatedRows() const { return m_repeated; }
    /// Rows dropped from the oldest end because the history was full.
    std::uint64_t droppedRows() const { return m_dropped; }
    /// Bytes held by the ring (values and sample numbers).
    std::size_t bytes() const;

    /// The newest `rows` rows (all when 0 or more than kept), oldest first, as a roll capture.
    ScopeCapture snapshot(std::size_t rows = 0) const;

private:
    std::vector<ScopeChannelInfo> m_channels;
    double m_rateHz = 0.0;
    std::size_t m_capacity = 0;
    std::vector<std::vector<double>> m_values; ///< per channel, m_capacity each
    std::vector<std::uint64_t> m_samples;      ///< m_capacity
    std::size_t m_head = 0;                    ///< slot of the next row
    std::size_t m_count = 0;
    std::uint64_t m_newest = 0;
    std::uint64_t m_lost = 0;
    std::uint64_t m_repeated = 0;
    std::uint64_t m_dropped = 0;
};

/// The inverse of scopeCaptureToTable: a table with a `sample` column, metadata fs_Hz and unit.CHANNEL (as
/// the scope CSV, io::readScopeCsv, and the store give it back). triggered/triggerSample from the metadata
/// (scope_mode, trigger_sample). Errors name the missing or bad field.
Result<ScopeCapture> scopeCaptureFromTable(const model::Capture& table);

} // namespace axistune::device
