#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Fills translations/axistune_ja.ts from the table below (terms from shared/GLOSSARY-ja.md).
# Run after lupdate; it fails when a source text has no Japanese here, so nothing stays unfinished.
# More tables: translations/ja/*.json ({"source": "Japanese", ...}, one file per part of the app).
# `fill_ja.py --missing [FILE]` lists the source texts without Japanese as a JSON object to fill.
import glob
import json
import os
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
    # Drive parameters (context "Parameter")
    'Maximum current (peak)': '最大電流 (ピーク)',
    'Rated current (peak)': '定格電流 (ピーク)',
    'Torque constant': 'トルク定数',
    'Maximum voltage': '最大電圧',
    'Current-loop period': '電流ループ周期',
    'Current proportional gain k_p': '電流比例ゲイン k_p',
    'Current integral gain k_i': '電流積分ゲイン k_i',
    'PI ratio α': 'PI率 α',
    'Dead time': 'むだ時間',
    'Velocity-loop period': '速度ループ周期',
    'Velocity proportional gain': '速度比例ゲイン',
    'Velocity integral gain': '速度積分ゲイン',
    'Velocity integral divider': '速度積分の分周比',
    'Inertia for torque feedforward': 'トルクフィードフォワード用イナーシャ',
    'Position-loop period': '位置ループ周期',
    'Position gain': '位置ゲイン',
    'Velocity feedforward': '速度フィードフォワード',
    'Torque feedforward': 'トルクフィードフォワード',
    'Feedback (0 semi-closed, 1 full-closed)': 'フィードバック (0 セミクローズド, 1 フルクローズド)',
    'Torque low-pass cutoff (0 = off)': 'トルク指令ローパスフィルタ遮断周波数 (0 = 無効)',
    'Lost-motion compensation (0 off, 1 conventional, 2 proposed)': 'ロストモーション補正 (0 無効, 1 従来法, 2 提案法)',
    'Conventional backlash amount': '従来法のバックラッシ補正量',
    'Lost-motion coefficient A': 'ロストモーション係数 A',
    'Lost-motion coefficient B': 'ロストモーション係数 B',
    'Ball-screw length offset x0': 'ボールねじ長さオフセット x0',
    'Trace divider (of the velocity period)': 'トレース分周比 (速度ループ周期の倍数)',
    'Notch 1 centre': 'ノッチフィルタ 1 中心周波数',
    'Notch 1 width': 'ノッチフィルタ 1 帯域幅',
    'Notch 1 depth': 'ノッチフィルタ 1 深さ',
    'Notch 2 centre': 'ノッチフィルタ 2 中心周波数',
    'Notch 2 width': 'ノッチフィルタ 2 帯域幅',
    'Notch 2 depth': 'ノッチフィルタ 2 深さ',
    'Notch 3 centre': 'ノッチフィルタ 3 中心周波数',
    'Notch 3 width': 'ノッチフィルタ 3 帯域幅',
    'Notch 3 depth': 'ノッチフィルタ 3 深さ',
    'Notch 4 centre': 'ノッチフィルタ 4 中心周波数',
    'Notch 4 width': 'ノッチフィルタ 4 帯域幅',
    'Notch 4 depth': 'ノッチフィルタ 4 深さ',
}

here = os.path.dirname(os.path.abspath(__file__))
for f in sorted(glob.glob(os.path.join(here, "ja", "*.json"))):
    with open(f, encoding="utf-8") as fh:
        JA.update(json.load(fh))

args = [a for a in sys.argv[1:] if a != "--missing"]
path = args[0] if args else os.path.join(here, "axistune_ja.ts")
tree = ET.parse(path)
if "--missing" in sys.argv:
    todo = {}
    for msg in tree.iter("message"):
        src = msg.find("source").text or ""
        if src not in JA:
            todo[src] = ""
    print(json.dumps(todo, ensure_ascii=False, indent=1))
    sys.exit(0)
missing = []
for msg in tree.iter("message"):
    src = msg.find("source").text or ""
    tr = msg.find("translation")
    if src not in JA:
        missing.append(src)
        continue
    forms = tr.findall("numerusform")
    if msg.get("numerus") == "yes":
        # Japanese has one plural form: every numerusform gets the same text.
        if not forms:
            forms = [ET.SubElement(tr, "numerusform")]
        for form in forms:
            form.text = JA[src]
    else:
        tr.text = JA[src]
    tr.attrib.pop("type", None)
tree.write(path, encoding="utf-8", xml_declaration=True)
if missing:
    sys.exit("no Japanese for: " + "; ".join(missing))
