// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers of the one-button tuning wizard's GUI tests (tst_autotunewizard, tst_autotuneundo): every parameter of an
// axis read through the DriveController, and a store with an embedded simulator connected.

#include "app/gui/AppContext.h"

#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/GuiTestUtil.h"

namespace axistune::testing {

/// Every parameter of `axis` read through the DriveController (empty when the read fails).
inline model::ParameterValues readAll(gui::AppContext& ctx, const QString& axis)
{
    model::ParameterValues out;
    bool done = false;
    auto* req = ctx.drive().readParameters(axis);
    QObject::connect(req, &gui::DriveRequest::finished, [&](const gui::DriveReply& r) {
        if (r.ok)
            out = r.values;
        done = true;
    });
    waitUntil([&] { return done; }, 20000);
    return out;
}

/// A store in `dir`, the embedded `uri` connected, every parameter of `axis` as found.
inline void openOn(QTemporaryDir& dir, gui::AppContext& ctx, model::ParameterValues& before,
                   const char* uri = "sim:vmc", const QString& axis = "X")
{
    QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
    ctx.drive().connectTo(uri);
    QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
    before = readAll(ctx, axis);
}

} // namespace axistune::testing
