<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="ja">
<context>
    <name>axistune::gui::MainWindow</name>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="37" />
        <source>AxisTune</source>
        <translation>AxisTune</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="38" />
        <source>&amp;Machine</source>
        <translation>機械(&amp;M)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="39" />
        <source>&amp;Connect…</source>
        <translation>接続(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="41" />
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="45" />
        <source>Machine / axis</source>
        <translation>機械 / 軸</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="49" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="49" />
        <source>Key</source>
        <translation>キー</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="49" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="49" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="49" />
        <source>Limits</source>
        <translation>範囲</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="57" />
        <source>Not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="71" />
        <source>Connection failed</source>
        <translation>接続に失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="72" />
        <source>Could not start the simulated machine: %1</source>
        <translation>シミュレーション機を起動できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="77" />
        <source>Connected: simulated machine %1</source>
        <translation>接続中: シミュレーション機 %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="104" />
        <source>Reading the parameters of axis %1 failed</source>
        <translation>軸 %1 のパラメータの読み出しに失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="118" />
        <source>%1 … %2%3</source>
        <translation>%1 … %2%3</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="120" />
        <source> (read-only)</source>
        <translation> (読み出し専用)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="123" />
        <source>Axis %1: %2 parameters read from the drive</source>
        <translation>軸 %1: サーボアンプから %2 個のパラメータを読み出しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="133" />
        <source>Connect</source>
        <translation>接続</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="133" />
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