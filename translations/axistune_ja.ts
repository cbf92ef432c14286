<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="ja">
<context>
    <name>Parameter</name>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="14" />
        <source>Maximum current (peak)</source>
        <translation>最大電流 (ピーク)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="15" />
        <source>Rated current (peak)</source>
        <translation>定格電流 (ピーク)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="16" />
        <source>Torque constant</source>
        <translation>トルク定数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="17" />
        <source>Maximum voltage</source>
        <translation>最大電圧</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="18" />
        <source>Current-loop period</source>
        <translation>電流ループ周期</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="19" />
        <source>Current proportional gain k_p</source>
        <translation>電流比例ゲイン k_p</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="20" />
        <source>Current integral gain k_i</source>
        <translation>電流積分ゲイン k_i</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="21" />
        <source>PI ratio α</source>
        <translation>PI率 α</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="22" />
        <source>Dead time</source>
        <translation>むだ時間</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="23" />
        <source>Velocity-loop period</source>
        <translation>速度ループ周期</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="24" />
        <source>Velocity proportional gain</source>
        <translation>速度比例ゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="25" />
        <source>Velocity integral gain</source>
        <translation>速度積分ゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="26" />
        <source>Velocity integral divider</source>
        <translation>速度積分の分周比</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="27" />
        <source>Inertia for torque feedforward</source>
        <translation>トルクフィードフォワード用イナーシャ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="28" />
        <source>Position-loop period</source>
        <translation>位置ループ周期</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="29" />
        <source>Position gain</source>
        <translation>位置ゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="30" />
        <source>Velocity feedforward</source>
        <translation>速度フィードフォワード</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="31" />
        <source>Torque feedforward</source>
        <translation>トルクフィードフォワード</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="32" />
        <source>Feedback (0 semi-closed, 1 full-closed)</source>
        <translation>フィードバック (0 セミクローズド, 1 フルクローズド)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="33" />
        <source>Notch 1 centre</source>
        <translation>ノッチフィルタ 1 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="34" />
        <source>Notch 1 width</source>
        <translation>ノッチフィルタ 1 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="35" />
        <source>Notch 1 depth</source>
        <translation>ノッチフィルタ 1 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="36" />
        <source>Notch 2 centre</source>
        <translation>ノッチフィルタ 2 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="37" />
        <source>Notch 2 width</source>
        <translation>ノッチフィルタ 2 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="38" />
        <source>Notch 2 depth</source>
        <translation>ノッチフィルタ 2 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="39" />
        <source>Notch 3 centre</source>
        <translation>ノッチフィルタ 3 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="40" />
        <source>Notch 3 width</source>
        <translation>ノッチフィルタ 3 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="41" />
        <source>Notch 3 depth</source>
        <translation>ノッチフィルタ 3 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="42" />
        <source>Notch 4 centre</source>
        <translation>ノッチフィルタ 4 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="43" />
        <source>Notch 4 width</source>
        <translation>ノッチフィルタ 4 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="44" />
        <source>Notch 4 depth</source>
        <translation>ノッチフィルタ 4 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="45" />
        <source>Torque low-pass cutoff (0 = off)</source>
        <translation>トルク指令ローパスフィルタ遮断周波数 (0 = 無効)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="46" />
        <source>Lost-motion compensation (0 off, 1 conventional, 2 proposed)</source>
        <translation>ロストモーション補正 (0 無効, 1 従来法, 2 提案法)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="47" />
        <source>Conventional backlash amount</source>
        <translation>従来法のバックラッシ補正量</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="48" />
        <source>Lost-motion coefficient A</source>
        <translation>ロストモーション係数 A</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="49" />
        <source>Lost-motion coefficient B</source>
        <translation>ロストモーション係数 B</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="50" />
        <source>Ball-screw length offset x0</source>
        <translation>ボールねじ長さオフセット x0</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="51" />
        <source>Trace divider (of the velocity period)</source>
        <translation>トレース分周比 (速度ループ周期の倍数)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MainWindow</name>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="39" />
        <source>AxisTune</source>
        <translation>AxisTune</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="40" />
        <source>&amp;Machine</source>
        <translation>機械(&amp;M)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="41" />
        <source>&amp;Connect…</source>
        <translation>接続(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="43" />
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="47" />
        <source>Machine / axis</source>
        <translation>機械 / 軸</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="51" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="51" />
        <source>Key</source>
        <translation>キー</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="51" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="51" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="51" />
        <source>Limits</source>
        <translation>範囲</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="59" />
        <source>Not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="73" />
        <source>Connection failed</source>
        <translation>接続に失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="74" />
        <source>Could not start the simulated machine: %1</source>
        <translation>シミュレーション機を起動できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="79" />
        <source>Connected: simulated machine %1</source>
        <translation>接続中: シミュレーション機 %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="106" />
        <source>Reading the parameters of axis %1 failed</source>
        <translation>軸 %1 のパラメータの読み出しに失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="120" />
        <source>%1 … %2%3</source>
        <translation>%1 … %2%3</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="122" />
        <source> (read-only)</source>
        <translation> (読み出し専用)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="125" />
        <source>Axis %1: %2 parameters read from the drive</source>
        <translation>軸 %1: サーボアンプから %2 個のパラメータを読み出しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="135" />
        <source>Connect</source>
        <translation>接続</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="135" />
        <source>Built-in simulated machine:</source>
        <translation>内蔵シミュレーション機:</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="19" />
        <source>Commissioning and tuning of NC feed axes</source>
        <translation>NC工作機械送り軸の立上げと調整</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="22" />
        <source>Simulated machine preset (vmc, dd-table, two-inertia).</source>
        <translation>シミュレーション機のプリセット (vmc, dd-table, two-inertia)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="24" />
        <source>Language: en or ja.</source>
        <translation>言語: en または ja。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="25" />
        <source>Save a screenshot of the main window and quit.</source>
        <translation>メインウィンドウのスクリーンショットを保存して終了します。</translation>
    </message>
</context>
</TS>