#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Fills translations/axistune_ja.ts from the table below (terms from shared/GLOSSARY-ja.md).
# Run after lupdate; it fails when a source text has no Japanese here, so nothing stays unfinished.
import sys
import xml.etree.ElementTree as ET

JA = {
    "AxisTune": "AxisTune",
    "&Machine": "機械(&M)",
    "&Connect…": "接続(&C)…",
    "&Quit": "終了(&Q)",
    "Machine / axis": "機械 / 軸",
    "Parameter": "パラメータ",
    "Key": "キー",
    "Value": "値",
    "Unit": "単位",
    "Limits": "範囲",
    "Not connected": "未接続",
    "Connection failed": "接続に失敗しました",
    "Could not start the simulated machine: %1": "シミュレーション機を起動できませんでした: %1",
    "Connected: simulated machine %1": "接続中: シミュレーション機 %1",
    "Reading the parameters of axis %1 failed": "軸 %1 のパラメータの読み出しに失敗しました",
    "%1 … %2%3": "%1 … %2%3",
    " (read-only)": " (読み出し専用)",
    "Axis %1: %2 parameters read from the drive": "軸 %1: サーボアンプから %2 個のパラメータを読み出しました",
    "Connect": "接続",
    "Built-in simulated machine:": "内蔵シミュレーション機:",
    "Commissioning and tuning of NC feed axes": "NC工作機械送り軸の立上げと調整",
    "Simulated machine preset (vmc, dd-table, two-inertia).": "シミュレーション機のプリセット (vmc, dd-table, two-inertia)。",
    "Language: en or ja.": "言語: en または ja。",
    "Save a screenshot of the main window and quit.": "メインウィンドウのスクリーンショットを保存して終了します。",
}

path = sys.argv[1] if len(sys.argv) > 1 else "translations/axistune_ja.ts"
tree = ET.parse(path)
missing = []
for msg in tree.iter("message"):
    src = msg.find("source").text or ""
    tr = msg.find("translation")
    if src not in JA:
        missing.append(src)
        continue
    tr.text = JA[src]
    tr.attrib.pop("type", None)
tree.write(path, encoding="utf-8", xml_declaration=True)
if missing:
    sys.exit("no Japanese for: " + "; ".join(missing))
