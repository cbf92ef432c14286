// SPDX-License-Identifier: GPL-3.0-or-later
// Store schema migrations (docs/storage.md "Schema").
#include "core/store/Schema.h"

namespace axistune::store {

const std::vector<Migration>& migrations()
{
    static const std::vector<Migration> list{
        {1, "initial schema: machines, axes, parameter sets, models, sessions, captures, results, journal",
         R"sql(
CREATE TABLE machines (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  description TEXT NOT NULL DEFAULT '',
  created TEXT NOT NULL
);
CREATE TABLE axes (
  id INTEGER PRIMARY KEY,
  machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
  name TEXT NOT NULL,
  position INTEGER NOT NULL,
  UNIQUE (machine_id, name)
);
CREATE TABLE sessions (
  id INTEGER PRIMARY KEY,
  machine_id INTEGER REFERENCES machines(id) ON DELETE SET NULL,
  axis TEXT NOT NULL DEFAULT '',
  kind TEXT NOT NULL,
  started TEXT NOT NULL,
  finished TEXT NOT NULL,
  status TEXT NOT NULL CHECK (status IN ('completed', 'aborted', 'failed')),
  app_version TEXT NOT NULL,
  inputs TEXT NOT NULL DEFAULT '{}'
);
CREATE TABLE parameter_sets (
  id INTEGER PRIMARY KEY,
  axis_id INTEGER NOT NULL REFERENCES axes(id) ON DELETE CASCADE,
  source TEXT NOT NULL CHECK (source IN ('read', 'proposed', 'applied', 'imported')),
  time TEXT NOT NULL,
  note TEXT NOT NULL DEFAULT '',
  session_id INTEGER REFERENCES sessions(id) ON DELETE SET NULL
);
CREATE TABLE parameter_values (
  set_id INTEGER NOT NULL REFERENCES parameter_sets(id) ON DELETE CASCADE,
  key TEXT NOT NULL,
  value REAL NOT NULL,
  PRIMARY KEY (set_id, key)
) WITHOUT ROWID;
CREATE TABLE models (
  id INTEGER PRIMARY KEY,
  axis_id INTEGER NOT NULL REFERENCES axes(id) ON DELETE CASCADE,
  kind TEXT NOT NULL CHECK (kind IN ('motor', 'two_inertia', 'lost_motion', 'modal')),
  time TEXT NOT NULL,
  data TEXT NOT NULL,
  session_id INTEGER REFERENCES sessions(id) ON DELETE SET NULL
);
CREATE TABLE captures (
  id INTEGER PRIMARY KEY,
  session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  position INTEGER NOT NULL,
  name TEXT NOT NULL,
  metadata TEXT NOT NULL,
  samples INTEGER NOT NULL
);
CREATE TABLE capture_channels (
  id INTEGER PRIMARY KEY,
  capture_id INTEGER NOT NULL REFERENCES captures(id) ON DELETE CASCADE,
  position INTEGER NOT NULL,
  name TEXT NOT NULL,
  data BLOB NOT NULL
);
CREATE TABLE results (
  id INTEGER PRIMARY KEY,
  session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  position INTEGER NOT NULL,
  name TEXT NOT NULL,
  data TEXT NOT NULL
);
CREATE TABLE result_arrays (
  id INTEGER PRIMARY KEY,
  result_id INTEGER NOT NULL REFERENCES results(id) ON DELETE CASCADE,
  position INTEGER NOT NULL,
  name TEXT NOT NULL,
  data BLOB NOT NULL
);
CREATE TABLE journal (
  id INTEGER PRIMARY KEY,
  axis_id INTEGER NOT NULL REFERENCES axes(id) ON DELETE CASCADE,
  key TEXT NOT NULL,
  old_value REAL,
  new_value REAL NOT NULL,
  time TEXT NOT NULL,
  session_id INTEGER REFERENCES sessions(id) ON DELETE SET NULL
);
)sql"},
        {2, "sessions gain operator and note; indexes for listing sessions and reading an axis's history",
         R"sql(
ALTER TABLE sessions ADD COLUMN operator TEXT NOT NULL DEFAULT '';
ALTER TABLE sessions ADD COLUMN note TEXT NOT NULL DEFAULT '';
CREATE INDEX sessions_machine ON sessions(machine_id);
CREATE INDEX captures_session ON captures(session_id);
CREATE INDEX capture_channels_capture ON capture_channels(capture_id);
CREATE INDEX results_session ON results(session_id);
CREATE INDEX result_arrays_result ON result_arrays(result_id);
CREATE INDEX parameter_sets_axis ON parameter_sets(axis_id);
CREATE INDEX models_axis ON models(axis_id);
CREATE INDEX journal_axis ON journal(axis_id);
)sql"},
        // No table changes: the version tells an older AxisTune, which reads capture metadata only as strings, to
        // refuse the file ("written by a newer AxisTune") rather than fail on the first session it loads.
        {3, "capture metadata values may be JSON numbers (model::Metadata); strings of earlier versions still read",
         R"sql(
-- captures.metadata: {"fs_Hz": 4000, "test": "step"}; version 2 wrote {"fs_Hz": "4000", "test": "step"}
)sql"},
    };
    return list;
}

}  // namespace axistune::store
