<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="ja">
<context>
    <name>BallBarText</name>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="29" />
        <source>Circularity</source>
        <translation>真円度</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="30" />
        <source>Centre offset X</source>
        <translation>中心ずれ X</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="31" />
        <source>Centre offset Y</source>
        <translation>中心ずれ Y</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="32" />
        <source>Radius deviation</source>
        <translation>半径偏差</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="33" />
        <source>Scale mismatch</source>
        <translation>スケール誤差の差</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="34" />
        <source>Squareness</source>
        <translation>直角度</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="35" />
        <source>Servo mismatch</source>
        <translation>サーボゲインの不一致</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="36" />
        <source>Backlash X</source>
        <translation>バックラッシ X</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="37" />
        <source>Backlash Y</source>
        <translation>バックラッシ Y</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="38" />
        <source>Reversal spike X</source>
        <translation>象限突起 X</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="39" />
        <source>Reversal spike Y</source>
        <translation>象限突起 Y</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="40" />
        <source>Cyclic error X</source>
        <translation>周期誤差 X</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="41" />
        <source>Cyclic error Y</source>
        <translation>周期誤差 Y</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="50" />
        <source>sin2θ coefficient k of each run; k = γR/2 + σvΔτ/2 solved for γ over CW and CCW runs (the part that keeps its sign with direction); positive = angle between +X and +Y below 90°</source>
        <translation>各測定の sin2θ 係数 k。k = γR/2 + σvΔτ/2 を CW と CCW の測定から γ について解く（方向で符号が変わらない成分）。正 = +X と +Y のなす角が 90° より小さい</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="54" />
        <source>the sin2θ part that changes sign with travel direction, Δτ from k = γR/2 + σvΔτ/2; positive = X lags Y</source>
        <translation>送り方向で符号が変わる sin2θ 成分。k = γR/2 + σvΔτ/2 から Δτ を求める。正 = X が Y より遅れる</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="58" />
        <source>γ = 2k/R from the sin2θ coefficient k of runs in one direction only: includes any servo mismatch (measure CW and CCW to separate them)</source>
        <translation>一方向だけの測定の sin2θ 係数 k から γ = 2k/R。サーボゲインの不一致を含む（分離するには CW と CCW を測定する）</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="62" />
        <source>Servo mismatch: needs runs in both directions (CW and CCW); only %1 given</source>
        <translation>サーボゲインの不一致: 両方向（CW と CCW）の測定が必要です。%1 だけが与えられました</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="64" />
        <source>largest least-squares sinusoid of the %1 coordinate (pitch scanned from the sampling limit to R/2, best pitch %2 mm) in the residual of the smooth fit, projected radially; detected against a noise threshold of %3 µm (false alarm ≈ 1e-3)</source>
        <translation>滑らかな当てはめの残差に含まれる %1 座標の最大の最小二乗正弦波（ピッチはサンプリング限界から R/2 まで探索、最適ピッチ %2 mm）を半径方向に投影。ノイズしきい値 %3 µm に対して検出（誤検出確率 ≈ 1e-3）</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="69" />
        <source>largest least-squares sinusoid of the %1 coordinate (pitch scanned from the sampling limit to R/2, best pitch %2 mm) in the residual of the smooth fit, projected radially; not detected against a noise threshold of %3 µm (false alarm ≈ 1e-3)</source>
        <translation>滑らかな当てはめの残差に含まれる %1 座標の最大の最小二乗正弦波（ピッチはサンプリング限界から R/2 まで探索、最適ピッチ %2 mm）を半径方向に投影。ノイズしきい値 %3 µm に対して検出されず（誤検出確率 ≈ 1e-3）</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="77" />
        <source>a backlash: |step| above %1 µm (4× its standard error, at least 0.3 µm)</source>
        <translation>|段差| が %1 µm（標準誤差の 4 倍、最小 0.3 µm）を超えるのでバックラッシと判定</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="78" />
        <source>no backlash: |step| not above %1 µm (4× its standard error, at least 0.3 µm)</source>
        <translation>|段差| が %1 µm（標準誤差の 4 倍、最小 0.3 µm）以下なのでバックラッシではない</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="81" />
        <source>mean radial step across %1 %2 reversal(s) (%3): joint fit of a cubic plus a step over %4–%5° each side of the reversal, where a spike has decayed; positive = outward step (lost motion), negative = inward (over-compensation); %6</source>
        <translation>%1 回の %2 反転（%3）での半径方向の段差の平均。象限突起が減衰した反転の両側 %4–%5° で 3 次式と段差を同時に当てはめる。正 = 外向きの段差（ロストモーション）、負 = 内向き（補正過剰）。%6</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="87" />
        <source>Backlash: no %1 reversal is covered by the trace(s)</source>
        <translation>バックラッシ: トレースに %1 の反転が含まれていません</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="89" />
        <source>transient at %1°, within ±%2° of a %3 reversal (width %4° at half height): the peak departure from the step's own transition (the level before the reversal, then a monotonic move to the level after it, which a backlash follows) that comes back to that level; reported when above 4× the fit-window noise and 0.3 µm</source>
        <translation>%3 反転の ±%2° 以内、%1° での象限突起（半値幅 %4°）: 段差そのものの遷移（反転前のレベルから反転後のレベルへの単調な移行で、バックラッシはこれに従う）から離れて元のレベルに戻る偏差のピーク。当てはめ窓のノイズの 4 倍かつ 0.3 µm を超えるとき報告</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="95" />
        <source>max − min radial deviation after removing the least-squares circle (ISO 230-4), the largest over the runs</source>
        <translation>最小二乗円を除いた半径偏差の最大 − 最小（ISO 230-4）、測定のうち最大のもの</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="99" />
        <source>least-squares circle centre offset along X (mean of runs)</source>
        <translation>最小二乗円の中心の X 方向ずれ（測定の平均）</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="101" />
        <source>least-squares circle centre offset along Y (mean of runs)</source>
        <translation>最小二乗円の中心の Y 方向ずれ（測定の平均）</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="103" />
        <source>least-squares circle radius minus the nominal radius (includes mean scale error and ball-bar length error)</source>
        <translation>最小二乗円の半径 − 呼び半径（平均スケール誤差とボールバー長さの誤差を含む）</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="107" />
        <source>εx − εy = 2c/R from the cos2θ coefficient c of the joint fit (circle, 2nd harmonics, lost motion) outside the reversal zones; positive = X travels further than Y</source>
        <translation>反転域外での同時当てはめ（円、2 次高調波、ロストモーション）の cos2θ 係数 c から εx − εy = 2c/R。正 = X が Y より長く動く</translation>
    </message>
    <message>
        <location filename="../app/gui/BallBarText.cpp" line="111" />
        <source>%1: centre, radius, circularity, scale mismatch, squareness, servo mismatch and cyclic error not computed: they need a full 360° circle, but the trace is a partial arc covering %2° (from %3° to %4° CCW; largest gap %5°, at most %6° allowed)</source>
        <translation>%1: 中心、半径、真円度、スケール誤差の差、直角度、サーボゲインの不一致、周期誤差は計算しません。360° の全円が必要ですが、トレースは %2° の部分円弧です（CCW で %3° から %4° まで。最大の欠け %5°、許容 %6°）</translation>
    </message>
</context>
<context>
    <name>CurrentLoopWizard</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="45" />
        <source>overshoot %1 %, 10–90 % rise time %2 µs</source>
        <translation>オーバーシュート %1 %、10–90 % 立ち上がり時間 %2 µs</translation>
    </message>
</context>
<context>
    <name>DriveController</name>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="36" />
        <source>Not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="154" />
        <source>Read-back of %1 on axis %2 gave %3 instead of %4</source>
        <translation>軸 %2 の %1 の読み出し値が %4 ではなく %3 でした</translation>
    </message>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="202" />
        <source>Aborted by the user</source>
        <translation>ユーザーにより中止されました</translation>
    </message>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="43" />
        <source>Aborted by the user before the test started</source>
        <translation>テスト開始前にユーザーにより中止されました</translation>
    </message>
</context>
<context>
    <name>DriveRegistry</name>
    <message>
        <location filename="../core/device/SimBackend.cpp" line="86" />
        <source>Built-in simulated machine</source>
        <translation>内蔵シミュレーション機</translation>
    </message>
    <message>
        <location filename="../core/device/SimBackend.cpp" line="92" />
        <source>Machine preset</source>
        <translation>機械のプリセット</translation>
    </message>
    <message>
        <location filename="../core/device/SimBackend.cpp" line="96" />
        <source>Identified model (optional)</source>
        <translation>同定したモデル (任意)</translation>
    </message>
    <message>
        <location filename="../core/device/SimBackend.cpp" line="98" />
        <source>result JSON of Identify from motion</source>
        <translation>「動作からの同定」の結果 JSON</translation>
    </message>
    <message>
        <location filename="../core/device/SimBackend.cpp" line="100" />
        <source>Axis of the model</source>
        <translation>モデルを適用する軸</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="14" />
        <source>Drive over Modbus TCP</source>
        <translation>Modbus TCP 経由のサーボアンプ</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="20" />
        <source>Host</source>
        <translation>ホスト</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="22" />
        <source>host name or address of the drive</source>
        <translation>サーボアンプのホスト名またはアドレス</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="24" />
        <source>Port</source>
        <translation>ポート</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="28" />
        <source>Response timeout</source>
        <translation>応答タイムアウト</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="32" />
        <source>Register map</source>
        <translation>レジスタマップ</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="34" />
        <source>family of resources/drives/FAMILY.json</source>
        <translation>resources/drives/FAMILY.json のファミリー名</translation>
    </message>
    <message>
        <location filename="../core/device/replay/ReplayDrive.cpp" line="251" />
        <source>Replay of a recorded capture</source>
        <translation>記録したキャプチャの再生</translation>
    </message>
    <message>
        <location filename="../core/device/replay/ReplayDrive.cpp" line="256" />
        <source>Capture file</source>
        <translation>キャプチャファイル</translation>
    </message>
    <message>
        <location filename="../core/device/replay/ReplayDrive.cpp" line="257" />
        <source>capture CSV with test, axis and fs_Hz metadata</source>
        <translation>test, axis, fs_Hz のメタデータを持つキャプチャ CSV</translation>
    </message>
    <message>
        <location filename="../core/device/hal/LinuxCncDrive.cpp" line="368" />
        <source>LinuxCNC machine (INI file)</source>
        <translation>LinuxCNC の機械 (INI ファイル)</translation>
    </message>
    <message>
        <location filename="../core/device/hal/LinuxCncDrive.cpp" line="370" />
        <source>Attaches to a LinuxCNC running from this INI: its joints' pid instances and the INI keys that feed their gains are read from its HAL files; axes by their letters (docs/linuxcnc.md).</source>
        <translation>この INI で動作中の LinuxCNC に接続します。各ジョイントの pid インスタンスと、そのゲインを与える INI キーを HAL ファイルから読み取ります。軸は軸名の文字で指定します (docs/linuxcnc.md)。</translation>
    </message>
    <message>
        <location filename="../core/device/hal/LinuxCncDrive.cpp" line="374" />
        <source>INI file</source>
        <translation>INI ファイル</translation>
    </message>
    <message>
        <location filename="../core/device/hal/LinuxCncDrive.cpp" line="375" />
        <source>the INI LinuxCNC was started from</source>
        <translation>LinuxCNC を起動した INI</translation>
    </message>
    <message>
        <location filename="../core/device/hal/HalDrive.cpp" line="765" />
        <source>LinuxCNC HAL session</source>
        <translation>LinuxCNC の HAL セッション</translation>
    </message>
    <message>
        <location filename="../core/device/hal/HalDrive.cpp" line="767" />
        <source>Attaches to the running HAL session of LinuxCNC (or a bare HAL loop): an axis is a pid instance, units are the HAL's; halcmd from AXISTUNE_HALCMD (docs/linuxcnc.md).</source>
        <translation>動作中の LinuxCNC の HAL セッション (または HAL だけのループ) に接続します。軸は pid インスタンス、単位は HAL のものです。halcmd は AXISTUNE_HALCMD で指定できます (docs/linuxcnc.md)。</translation>
    </message>
    <message>
        <location filename="../core/device/SimBackend.cpp" line="88" />
        <source>The embedded simulated drive on a machine preset (docs/simulator.md); model=PATH puts an identified rigid-body model in place of one axis's plant.</source>
        <translation>機械プリセット上の内蔵シミュレーションサーボアンプ (docs/simulator.md)。model=PATH で 1 軸のプラントを同定した剛体モデルに置き換えます。</translation>
    </message>
    <message>
        <location filename="../core/device/ModbusBackend.cpp" line="16" />
        <source>A drive speaking a register map of resources/drives/ over Modbus TCP (docs/modbus.md); axis i answers on unit id base + i of the map.</source>
        <translation>resources/drives/ のレジスタマップで Modbus TCP により通信するサーボアンプ (docs/modbus.md)。軸 i はマップのユニット ID 基準値 + i で応答します。</translation>
    </message>
    <message>
        <location filename="../core/device/replay/ReplayDrive.cpp" line="253" />
        <source>Plays back a capture CSV of `axistune-cli capture` as a drive: only the recorded test on the recorded axis, parameters read-only (docs/drive-seam.md).</source>
        <translation>`axistune-cli capture` のキャプチャ CSV をサーボアンプとして再生します: 記録した軸の記録した試験のみ、パラメータは読み取り専用 (docs/drive-seam.md)。</translation>
    </message>
</context>
<context>
    <name>FrfResultPage</name>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="55" />
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="638" />
        <source>the open loop L = T/(1−T) of the measured T</source>
        <translation>測定した T の開ループ L = T/(1−T)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="639" />
        <source>the measured response</source>
        <translation>測定した応答</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="658" />
        <source>|plant|·ω² (flat for the rigid body of a torque drive; its peak at least 6 dB above its median)</source>
        <translation>|プラント|·ω² (トルク指令のサーボアンプでは剛体部分が平坦。ピークが中央値より 6 dB 以上高いもの)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="661" />
        <source>|plant|·ω (flat for a velocity drive; its peak at least 6 dB above its median)</source>
        <translation>|プラント|·ω (速度指令のサーボアンプでは平坦。ピークが中央値より 6 dB 以上高いもの)</translation>
    </message>
</context>
<context>
    <name>HistoryView</name>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="106" />
        <source>Resonance %1</source>
        <translation>共振 %1</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="124" />
        <source>Notch %1 centre</source>
        <translation>ノッチ %1 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="127" />
        <source>A applied</source>
        <translation>A 適用値</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="130" />
        <source>B applied</source>
        <translation>B 適用値</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="153" />
        <source>A identified</source>
        <translation>A 同定値</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="157" />
        <source>B identified</source>
        <translation>B 同定値</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="180" />
        <source>Circularity measured</source>
        <translation>真円度 測定値</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="184" />
        <source>Circularity after compensation</source>
        <translation>補正後の真円度</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="261" />
        <source>Resonance frequency</source>
        <translation>共振周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="263" />
        <source>Notch centre (applied)</source>
        <translation>ノッチ中心周波数 (適用値)</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="265" />
        <source>Lost motion A</source>
        <translation>ロストモーション A</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="267" />
        <source>Lost motion B</source>
        <translation>ロストモーション B</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="269" />
        <source>Circularity</source>
        <translation>真円度</translation>
    </message>
</context>
<context>
    <name>NotchProposePage</name>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="78" />
        <source>Slot %1 at %2 Hz: resonance %3 dB above its baseline, −3 dB width %4 Hz, open-loop gain %5 dB. Depth %6 = the smaller of %7 (peak back to its baseline) and %8 (open-loop gain down to %9 dB). Digital −3 dB width %10 Hz = resonance width / depth (the notch zeros on the mode's poles), kept between %4 Hz and %11 Hz; drive width parameter %12 Hz (pre-warped at %13 Hz).</source>
        <translation>スロット %1、%2 Hz: 共振はベースラインより %3 dB 高く、−3 dB 帯域幅 %4 Hz、開ループゲイン %5 dB。深さ %6 = %7 (ピークをベースラインまで下げる) と %8 (開ループゲインを %9 dB まで下げる) の小さい方。ディジタルの −3 dB 帯域幅 %10 Hz = 共振の帯域幅 / 深さ (ノッチの零点をモードの極に置く)、%4 Hz から %11 Hz の範囲に制限; サーボアンプの帯域幅パラメータ %12 Hz (%13 Hz でプリワープ)。</translation>
    </message>
</context>
<context>
    <name>NotchWizard</name>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="99" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="106" />
        <source>%1 dB at %2 Hz</source>
        <translation>%1 dB (%2 Hz)</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="100" />
        <source>no phase crossover in the band</source>
        <translation>帯域内に位相交差なし</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="103" />
        <source>%1° at %2 Hz</source>
        <translation>%1° (%2 Hz)</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="104" />
        <source>no gain crossover in the band</source>
        <translation>帯域内にゲイン交差なし</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="112" />
        <source>Gain margin</source>
        <translation>ゲイン余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="113" />
        <source>Phase margin</source>
        <translation>位相余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="114" />
        <source>Peak sensitivity</source>
        <translation>感度関数のピーク</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="15" />
        <source>Maximum current (peak)</source>
        <translation>最大電流 (ピーク)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="16" />
        <source>Rated current (peak)</source>
        <translation>定格電流 (ピーク)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="17" />
        <source>Torque constant</source>
        <translation>トルク定数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="18" />
        <source>Maximum voltage</source>
        <translation>最大電圧</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="19" />
        <source>Current-loop period</source>
        <translation>電流ループ周期</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="20" />
        <source>Current proportional gain k_p</source>
        <translation>電流比例ゲイン k_p</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="21" />
        <source>Current integral gain k_i</source>
        <translation>電流積分ゲイン k_i</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="22" />
        <source>PI ratio α</source>
        <translation>PI率 α</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="23" />
        <source>Dead time</source>
        <translation>むだ時間</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="24" />
        <source>Velocity-loop period</source>
        <translation>速度ループ周期</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="25" />
        <source>Velocity proportional gain</source>
        <translation>速度比例ゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="26" />
        <source>Velocity integral gain</source>
        <translation>速度積分ゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="27" />
        <source>Velocity integral divider</source>
        <translation>速度積分の分周比</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="28" />
        <source>Inertia for torque feedforward</source>
        <translation>トルクフィードフォワード用イナーシャ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="29" />
        <source>Position-loop period</source>
        <translation>位置ループ周期</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="30" />
        <source>Position gain</source>
        <translation>位置ゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="31" />
        <source>Velocity feedforward</source>
        <translation>速度フィードフォワード</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="32" />
        <source>Torque feedforward</source>
        <translation>トルクフィードフォワード</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="33" />
        <source>Feedback (0 semi-closed, 1 full-closed)</source>
        <translation>フィードバック (0 セミクローズド, 1 フルクローズド)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="34" />
        <source>Notch 1 centre</source>
        <translation>ノッチフィルタ 1 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="35" />
        <source>Notch 1 width</source>
        <translation>ノッチフィルタ 1 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="36" />
        <source>Notch 1 depth</source>
        <translation>ノッチフィルタ 1 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="37" />
        <source>Notch 2 centre</source>
        <translation>ノッチフィルタ 2 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="38" />
        <source>Notch 2 width</source>
        <translation>ノッチフィルタ 2 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="39" />
        <source>Notch 2 depth</source>
        <translation>ノッチフィルタ 2 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="40" />
        <source>Notch 3 centre</source>
        <translation>ノッチフィルタ 3 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="41" />
        <source>Notch 3 width</source>
        <translation>ノッチフィルタ 3 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="42" />
        <source>Notch 3 depth</source>
        <translation>ノッチフィルタ 3 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="43" />
        <source>Notch 4 centre</source>
        <translation>ノッチフィルタ 4 中心周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="44" />
        <source>Notch 4 width</source>
        <translation>ノッチフィルタ 4 帯域幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="45" />
        <source>Notch 4 depth</source>
        <translation>ノッチフィルタ 4 深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="46" />
        <source>Torque low-pass cutoff (0 = off)</source>
        <translation>トルク指令ローパスフィルタ遮断周波数 (0 = 無効)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="47" />
        <source>Lost-motion compensation (0 off, 1 conventional, 2 proposed)</source>
        <translation>ロストモーション補正 (0 無効, 1 従来法, 2 提案法)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="48" />
        <source>Conventional backlash amount</source>
        <translation>従来法のバックラッシ補正量</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="49" />
        <source>Lost-motion coefficient A</source>
        <translation>ロストモーション係数 A</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="50" />
        <source>Lost-motion coefficient B</source>
        <translation>ロストモーション係数 B</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="51" />
        <source>Ball-screw length offset x0</source>
        <translation>ボールねじ長さオフセット x0</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="52" />
        <source>Trace divider (of the velocity period)</source>
        <translation>トレース分周比 (速度ループ周期の倍数)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="53" />
        <source>Vibration-suppression filter (0 off, 1 semi-closed F_m, 2 full-closed F_L)</source>
        <translation>振動抑制フィルタ (0 なし、1 セミクローズド F_m、2 フルクローズド F_L)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="54" />
        <source>Suppression filter frequency f0</source>
        <translation>振動抑制フィルタの周波数 f0</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="55" />
        <source>Suppression filter damping zeta</source>
        <translation>振動抑制フィルタの減衰比 zeta</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="56" />
        <source>F_L time constant tau</source>
        <translation>F_L の時定数 tau</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="57" />
        <source>Reversal compensation pulse amplitude (velocity command)</source>
        <translation>象限突起補正パルスの振幅（速度指令）</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="58" />
        <source>Reversal compensation pulse time constant</source>
        <translation>象限突起補正パルスの時定数</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="60" />
        <source>Proportional gain P</source>
        <translation>比例ゲイン P</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="61" />
        <source>Integral gain I</source>
        <translation>積分ゲイン I</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="62" />
        <source>Derivative gain D</source>
        <translation>微分ゲイン D</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="63" />
        <source>Feedforward FF0</source>
        <translation>フィードフォワード FF0</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="64" />
        <source>Velocity feedforward FF1</source>
        <translation>速度フィードフォワード FF1</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="65" />
        <source>Acceleration feedforward FF2</source>
        <translation>加速度フィードフォワード FF2</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="66" />
        <source>Jerk feedforward FF3</source>
        <translation>加加速度フィードフォワード FF3</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="67" />
        <source>Output bias</source>
        <translation>出力バイアス</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="68" />
        <source>Deadband</source>
        <translation>不感帯</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="69" />
        <source>Error limit</source>
        <translation>偏差制限</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="70" />
        <source>Integrator limit</source>
        <translation>積分制限</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="71" />
        <source>Error-rate limit</source>
        <translation>偏差変化率制限</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterText.cpp" line="72" />
        <source>Output limit</source>
        <translation>出力制限</translation>
    </message>
</context>
<context>
    <name>PlotExport</name>
    <message>
        <location filename="../widgets/PlotExport.cpp" line="55" />
        <source>%1: unknown image type '%2' (use .png, .svg or .pdf)</source>
        <translation>%1: 不明な画像形式 '%2' (.png、.svg または .pdf を使用してください)</translation>
    </message>
    <message>
        <location filename="../widgets/PlotExport.cpp" line="57" />
        <source>%1: the folder %2 does not exist</source>
        <translation>%1: フォルダ %2 が存在しません</translation>
    </message>
    <message>
        <location filename="../widgets/PlotExport.cpp" line="59" />
        <source>%1: negative image size %2×%3</source>
        <translation>%1: 画像サイズ %2×%3 が負です</translation>
    </message>
    <message>
        <location filename="../widgets/PlotExport.cpp" line="90" />
        <source>%1: could not write the image (is the folder writable and the disk not full?)</source>
        <translation>%1: 画像を書き込めませんでした (フォルダの書き込み権限とディスクの空き容量を確認してください)</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="117" />
        <source>%1: no stage.json given and the capture names no simulated machine/axis (metadata 'machine=' and 'axis=')</source>
        <translation>%1: stage.json の指定がなく、計測データにもシミュレーション機と軸の記載がありません (メタデータ 'machine=' と 'axis=')</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="124" />
        <source>axis parameters of %1 %2</source>
        <translation>%1 %2 の軸パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="140" />
        <source>%1: needs the columns t_s, current_A (or torque_Nm), motor_vel_rad_s, motor_pos_m, table_pos_m</source>
        <translation>%1: 列 t_s、current_A (または torque_Nm)、motor_vel_rad_s、motor_pos_m、table_pos_m が必要です</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="51" />
        <source>limit depth</source>
        <translation>限界切込み深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="50" />
        <source>[%1 values] %2 … %3</source>
        <translation>[%1 個の値] %2 … %3</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="460" />
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="297" />
        <source>the vmc preset has no X axis</source>
        <translation>vmc プリセットに X 軸がありません</translation>
    </message>
</context>
<context>
    <name>SessionFrf</name>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="83" />
        <location filename="../app/gui/WizardPages.cpp" line="88" />
        <source>Loading session %1 failed: %2</source>
        <translation>セッション %1 の読み込みに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="85" />
        <source>no store is open</source>
        <translation>データベースが開かれていません</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="96" />
        <source>Session %1 holds no frequency response.</source>
        <translation>セッション %1 に周波数応答はありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="99" />
        <source>Session %1, capture %2: %3</source>
        <translation>セッション %1、計測データ %2: %3</translation>
    </message>
</context>
<context>
    <name>SessionReport</name>
    <message>
        <location filename="../app/gui/Report.cpp" line="58" />
        <source>yes</source>
        <translation>はい</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="59" />
        <source>no</source>
        <translation>いいえ</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="127" />
        <source>completed</source>
        <translation>完了</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="129" />
        <source>ABORTED</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="131" />
        <source>FAILED</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="140" />
        <source>Read from the drive</source>
        <translation>サーボアンプから読み出し</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="142" />
        <source>Proposed</source>
        <translation>提案値</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="144" />
        <source>Applied</source>
        <translation>適用値</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="146" />
        <source>Imported</source>
        <translation>読み込み</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="218" />
        <source>Plot "%1" could not be rendered.</source>
        <translation>プロット "%1" を描画できませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="235" />
        <source>Session %1: %2</source>
        <translation>セッション %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="239" />
        <source>This session was %1. Reason: %2</source>
        <translation>このセッションは %1 でした。理由: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="241" />
        <location filename="../app/gui/Report.cpp" line="415" />
        <source>not recorded</source>
        <translation>記録なし</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="244" />
        <source>(none)</source>
        <translation>(なし)</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="245" />
        <source>Machine</source>
        <translation>機械</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="246" />
        <location filename="../app/gui/Report.cpp" line="406" />
        <source>Axis</source>
        <translation>軸</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="247" />
        <source>Kind</source>
        <translation>種類</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="248" />
        <source>Status</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="251" />
        <source>Started</source>
        <translation>開始</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="252" />
        <source>Finished</source>
        <translation>終了</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="253" />
        <source>Operator</source>
        <translation>作業者</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="255" />
        <source>Notes</source>
        <translation>メモ</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="257" />
        <source>AxisTune version</source>
        <translation>AxisTune バージョン</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="271" />
        <source>F_L (full-closed)</source>
        <translation>F_L (フルクローズド)</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="272" />
        <source>F_m (semi-closed)</source>
        <translation>F_m (セミクローズド)</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="273" />
        <source>: f₀ %1 Hz, ζ %2</source>
        <translation>: f₀ %1 Hz、ζ %2</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="277" />
        <source>, τ %1 ms</source>
        <translation>、τ %1 ms</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="278" />
        <source>Suppression filter</source>
        <translation>振動抑制フィルタ</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="281" />
        <source>Maximum load error (verification)</source>
        <translation>負荷側誤差の最大値 (検証)</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="282" />
        <source>measured %1° with the filter; predicted %2° without, %3° with it</source>
        <translation>測定値 フィルタあり %1°、予測値 フィルタなし %2°、フィルタあり %3°</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="292" />
        <source>Plots</source>
        <translation>プロット</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="302" />
        <source>FRF "%1" is unreadable: %2</source>
        <translation>周波数応答 "%1" を読み取れません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="312" />
        <source>Frequency response: %1</source>
        <translation>周波数応答: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="322" />
        <source>Capture: %1</source>
        <translation>計測データ: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="327" />
        <source>No plots recorded.</source>
        <translation>記録されたプロットはありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="352" />
        <source>Ball-bar traces: %1</source>
        <translation>ボールバーの軌跡: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="370" />
        <source>Result: %1</source>
        <translation>結果: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="377" />
        <source>Parameter sets</source>
        <translation>パラメータセット</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="381" />
        <source>axis %1, %2</source>
        <translation>軸 %1、%2</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="386" />
        <location filename="../app/gui/Report.cpp" line="407" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="387" />
        <source>Description</source>
        <translation>説明</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="388" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="402" />
        <source>Journal of writes</source>
        <translation>書き込み履歴</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="405" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="408" />
        <source>Old value</source>
        <translation>旧値</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="409" />
        <source>New value</source>
        <translation>新値</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="430" />
        <source>Results</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="436" />
        <source>Identified models</source>
        <translation>同定したモデル</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="439" />
        <source>axis %1</source>
        <translation>軸 %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="442" />
        <source>Verification</source>
        <translation>検証</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="447" />
        <source>No verification was recorded.</source>
        <translation>検証は記録されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="461" />
        <source>Arrays (values): %1</source>
        <translation>配列 (値の数): %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="472" />
        <location filename="../app/gui/Report.cpp" line="533" />
        <source>AxisTune session %1</source>
        <translation>AxisTune セッション %1</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="474" />
        <source>Inputs</source>
        <translation>入力</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="480" />
        <source>Report made by AxisTune from session %1 of the store.</source>
        <translation>データベースのセッション %1 から AxisTune が作成したレポートです。</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="518" />
        <source>Cannot write %1: %2</source>
        <translation>%1 を書き込めません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/Report.cpp" line="543" />
        <source>Cannot write %1</source>
        <translation>%1 を書き込めません</translation>
    </message>
</context>
<context>
    <name>TestRunPage</name>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="55" />
        <source>velocity step</source>
        <translation>速度ステップ</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="57" />
        <source>jog</source>
        <translation>ジョグ</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="59" />
        <source>position hold</source>
        <translation>位置保持</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="61" />
        <source>frequency response (%1)</source>
        <translation>周波数応答 (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="64" />
        <source>circle of %1 and %2</source>
        <translation>%1 軸と %2 軸の円弧補間テスト</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="67" />
        <source>current step</source>
        <translation>電流ステップ</translation>
    </message>
</context>
<context>
    <name>VelocityLoopWizard</name>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="55" />
        <source>–</source>
        <translation>–</translation>
    </message>
</context>
<context>
    <name>Wizards</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="25" />
        <source>Current loop…</source>
        <translation>電流ループ…</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizard.cpp" line="37" />
        <source>Frequency response…</source>
        <translation>周波数応答…</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="47" />
        <source>Lost motion…</source>
        <translation>ロストモーション…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="38" />
        <source>Machining (chatter)…</source>
        <translation>加工 (びびり振動)…</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="32" />
        <source>Notch filters…</source>
        <translation>ノッチフィルタ…</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="29" />
        <source>Two-inertia vibration suppression…</source>
        <translation>2慣性系の振動抑制…</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="32" />
        <source>Velocity and position loop…</source>
        <translation>速度ループと位置ループ…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="49" />
        <source>Automatic tuning (one button)…</source>
        <translation>自動調整 (ワンボタン)…</translation>
    </message>
</context>
<context>
    <name>axistune::gui::AbortGuard</name>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="21" />
        <source>Restored %1 from before the write.</source>
        <translation>%1を書き込み前の値に戻しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="22" />
        <source>The previous values of %1 were restored on the drive and read back.</source>
        <translation>%1の以前の値をサーボアンプに戻し、読み返しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="28" />
        <source>Restoring %1 failed (%2): the applied values may still be active on the drive.</source>
        <translation>%1を戻せませんでした (%2)。適用した値がサーボアンプで有効なままの可能性があります。</translation>
    </message>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="36" />
        <source>Connection lost: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="51" />
        <source>Cancelled by the operator.</source>
        <translation>作業者によりキャンセルされました。</translation>
    </message>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="66" />
        <source>Restoring %1 from before the write…</source>
        <translation>%1を書き込み前の値に戻しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/AbortGuard.cpp" line="70" />
        <source>Could not restore %1: the connection to the drive is lost. Check them on the drive before the axis runs again.</source>
        <translation>%1を戻せません: サーボアンプとの接続が切れました。軸を再び動かす前にサーボアンプで確認してください。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::AppContext</name>
    <message>
        <location filename="../app/gui/AppContext.cpp" line="38" />
        <source>Could not open the store %1: %2</source>
        <translation>データベース %1 を開けませんでした: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/AppContext.cpp" line="44" />
        <source>Store: %1</source>
        <translation>データベース: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AppContext.cpp" line="81" />
        <source>The session was not saved: no store is open</source>
        <translation>セッションは保存されませんでした: データベースが開かれていません</translation>
    </message>
    <message>
        <location filename="../app/gui/AppContext.cpp" line="97" />
        <source>Saving the session failed: %1</source>
        <translation>セッションの保存に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AppContext.cpp" line="99" />
        <source>Session %1 saved (%2, %3)</source>
        <translation>セッション %1 を保存しました (%2、%3)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::ApplyPage</name>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="374" />
        <location filename="../app/gui/WizardPages.cpp" line="387" />
        <source>Apply</source>
        <translation>適用</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="375" />
        <source>The parameters below change on the drive. Every value is read back after the write.</source>
        <translation>以下のパラメータをサーボアンプで変更します。書き込み後にすべての値を読み出して確認します。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="377" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="377" />
        <source>Key</source>
        <translation>キー</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="377" />
        <source>Device</source>
        <translation>サーボアンプ</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="377" />
        <source>Proposed</source>
        <translation>提案値</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="377" />
        <source>Read back</source>
        <translation>読み出し値</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="377" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="382" />
        <source>Write these values to the drive</source>
        <translation>これらの値をサーボアンプに書き込む</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="383" />
        <source>Do not apply now (keep the proposal in the session only)</source>
        <translation>今は適用しない (提案はセッションにのみ保存)</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="388" />
        <source>Restore previous values</source>
        <translation>以前の値に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="426" />
        <source>Not connected: the proposal can only be kept in the session.</source>
        <translation>未接続: 提案はセッションに保存するだけです。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="429" />
        <source>Reading the device values…</source>
        <translation>サーボアンプの値を読み出し中…</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="451" />
        <source>Changed</source>
        <translation>変更あり</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="465" />
        <source>The device values are not read yet: wait, then Apply.</source>
        <translation>サーボアンプの値をまだ読み出していません。少し待ってから適用してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="469" />
        <source>Writing…</source>
        <translation>書き込み中…</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="478" />
        <source>Restoring the previous values…</source>
        <translation>以前の値に戻しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="501" />
        <location filename="../app/gui/WizardPages.cpp" line="511" />
        <source>Reading the parameters failed: %1</source>
        <translation>パラメータの読み出しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="515" />
        <source>Changed values are highlighted. Confirm, then Apply.</source>
        <translation>変更される値は強調表示されています。確認してから適用してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="520" />
        <source>The write failed; the drive keeps its values: %1</source>
        <translation>書き込みに失敗しました。サーボアンプの値は変わっていません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="527" />
        <source>Applied and read back.</source>
        <translation>適用し、読み出して確認しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="531" />
        <source>Axis %1: %2 parameters applied and read back</source>
        <translation>軸 %1: %2 個のパラメータを適用し、読み出して確認しました</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="537" />
        <source>Restoring failed: %1</source>
        <translation>元に戻せませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="545" />
        <source>The previous values are back on the drive.</source>
        <translation>サーボアンプの値を以前の値に戻しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="549" />
        <source>Axis %1: previous parameters restored</source>
        <translation>軸 %1: 以前のパラメータに戻しました</translation>
    </message>
</context>
<context>
    <name>axistune::gui::AutoTuneChoicePage</name>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="127" />
        <source>Automatic tuning</source>
        <translation>自動調整</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="128" />
        <source>One run through the wizards' steps: safety envelope, current loop, adaptive frequency response, notch filters, velocity PI, position gain and feedforward, move evaluation, verify, then apply or roll back. Each step shows what it measured, what it chose and the rule that chose it. A refusal or Abort restores every parameter.</source>
        <translation>ウィザードの手順を一度に実行します: 安全範囲、電流ループ、適応周波数応答、ノッチフィルタ、速度PI、位置ゲインとフィードフォワード、移動評価、検証、そして適用または元に戻す。各手順は測定した値、選んだ値、選んだ規則を表示します。拒否または中止ではすべてのパラメータを元に戻します。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="136" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="140" />
        <source>designed for phase margin ≥ %1°, gain margin ≥ %2 dB, velocity crossover at least %3 Hz; the re-measured loop must keep ≥ %4° and ≥ %5 dB or the run rolls back</source>
        <translation>位相余裕 ≥ %1°、ゲイン余裕 ≥ %2 dB、速度ループのゲイン交差周波数 %3 Hz 以上で設計; 再測定したループが ≥ %4° と ≥ %5 dB を保たなければ元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="161" />
        <location filename="../app/gui/AutoTuneWizard.cpp" line="470" />
        <source>Gentle</source>
        <translation>ソフト</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="161" />
        <source>large margins for heavy or changing loads and little overshoot</source>
        <translation>重い負荷や変動する負荷、小さいオーバーシュートのための大きな余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="163" />
        <location filename="../app/gui/AutoTuneWizard.cpp" line="473" />
        <source>Standard</source>
        <translation>標準</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="163" />
        <source>the wizards' defaults</source>
        <translation>ウィザードの既定値</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="164" />
        <location filename="../app/gui/AutoTuneWizard.cpp" line="472" />
        <source>Stiff</source>
        <translation>高剛性</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="164" />
        <source>the highest bandwidth, for rigid axes</source>
        <translation>最も高い帯域、剛性の高い軸向け</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="166" />
        <source>Style:</source>
        <translation>スタイル:</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="173" />
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="174" />
        <source>Seconds of motion for the whole sequence; a step that would go beyond it stops the run and nothing is changed.</source>
        <translation>全手順の動作時間 (秒); これを超える手順があれば実行を止め、何も変更しません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="176" />
        <source>Time budget (motion):</source>
        <translation>時間予算 (動作):</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="218" />
        <source>Dry run: measure and design everything, then restore every parameter (nothing is applied)</source>
        <translation>試行のみ: すべてを測定・設計し、その後すべてのパラメータを元に戻す (何も適用しない)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="225" />
        <source>The axis may move: it is free within its travel window, and I can stop it (emergency stop at hand).</source>
        <translation>軸が動いてよい: ストローク範囲内に障害物がなく、停止できる (非常停止が手元にある)。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="232" />
        <source>Undo an earlier run…</source>
        <translation>以前の実行を元に戻す…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="260" />
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="185" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="186" />
        <source>the style's</source>
        <translation>スタイルの値</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="187" />
        <source>The velocity crossover the design must reach; a resonance within a factor 3 of it is refused. The style's value unless set.</source>
        <translation>設計が達すべき速度ループのゲイン交差周波数。その 3 倍以内にある共振は拒否します。設定しなければスタイルの値です。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="189" />
        <source>Required velocity crossover:</source>
        <translation>必要な速度ループ交差周波数:</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="194" />
        <source>off (where the axis stands)</source>
        <translation>オフ (軸の現在位置で)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="195" />
        <source> positions</source>
        <translation> 位置</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="196" />
        <source>Measure, design and verify at N positions spread evenly over the travel window; the gains must keep the margins at every one. The drive moves the axis between them.</source>
        <translation>ストローク範囲に均等に配置した N 位置で測定・設計・検証します。ゲインはすべての位置で余裕を保たなければなりません。位置の間はサーボアンプが軸を移動します。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="198" />
        <source>Over the travel:</source>
        <translation>ストローク全体で:</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="206" />
        <source>optional, e.g. 5, 10, 20</source>
        <translation>任意、例: 5, 10, 20</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="207" />
        <source>Amplitude map: the closed velocity loop measured at three or more increasing multisine peaks [% of rated torque]; lines whose response changes beyond the noise are marked non-linear, and the tuner designs from the amplitude nearest the torque of a move. One position only.</source>
        <translation>振幅マップ: 速度閉ループを 3 つ以上の増加するマルチサイン振幅 [定格トルク比 %] で測定します。応答がノイズを超えて変化する周波数線は非線形と表示され、調整は移動時のトルクに最も近い振幅から設計します。1 位置のみ。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="211" />
        <source>Amplitude map: amplitudes in % of rated torque:</source>
        <translation>振幅マップ: 加振振幅 (定格トルク比 %):</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="234" />
        <source>Puts back the parameters an earlier applied run of this wizard changed, from its saved session (a run of axistune-cli autotune: its --undo RESULT.json)</source>
        <translation>このウィザードの以前に適用した実行が変更したパラメータを、保存されたセッションから元に戻します (axistune-cli autotune の実行は --undo RESULT.json で)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="296" />
        <source>Asking the drive for the travel window…</source>
        <translation>サーボアンプにストローク範囲を問い合わせ中…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="303" />
        <location filename="../app/gui/AutoTuneWizard.cpp" line="305" />
        <source>Over the travel not available: %1</source>
        <translation>ストローク全体での調整は使えません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="309" />
        <source>m or rad</source>
        <translation>m または rad</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="319" />
        <source>Travel window −%1 … +%1 %2: the positions are spread evenly from one end to the other; the axis returns to where it stood.</source>
        <translation>ストローク範囲 −%1 … +%1 %2: 位置は一端から他端まで均等に配置され、終了後に軸は元の位置へ戻ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="361" />
        <source>Cannot start: %1</source>
        <translation>開始できません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="313" />
        <source>Travel window −%1 … +%1 %2: the positions are spread evenly from −%3 to +%3 %2, inside its ends by the servo lag of the moves between them (%4 %2: jog speed / position gain); the axis returns to where it stood.</source>
        <translation>ストローク範囲 −%1 … +%1 %2: 位置は −%3 から +%3 %2 まで均等に配置されます (両端から、位置間の移動の追従遅れによる位置偏差 %4 %2 = ジョグ速度 / 位置ゲイン だけ内側)。終了後に軸は元の位置へ戻ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="40" />
        <source>No store is open.</source>
        <translation>データベースが開かれていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="45" />
        <source>Reading session %1 failed: %2</source>
        <translation>セッション %1 の読み出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="50" />
        <source>Session %1 is not a run of the automatic tuning.</source>
        <translation>セッション %1 は自動調整の実行ではありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="55" />
        <source>Session %1: %2</source>
        <translation>セッション %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="59" />
        <source>Session %1 tuned axis %2, which this connection does not have.</source>
        <translation>セッション %1 は軸 %2 を調整しましたが、この接続にはその軸がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="78" />
        <source>Undo an earlier run</source>
        <translation>以前の実行を元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="80" />
        <source>Applied runs of the automatic tuning saved for %1, newest first. The next page shows what the chosen run changed; nothing is written before you confirm Undo there.</source>
        <translation>%1 に保存された自動調整の適用済み実行 (新しい順)。次のページで選んだ実行が変更した内容を表示します。そこで「元に戻す」を確認するまで何も書き込みません。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="101" />
        <source>Session %1 (%2), axis %3: %n parameter(s) applied</source>
        <translation>
            <numerusform>セッション %1 (%2)、軸 %3: %n 個のパラメータを適用</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="109" />
        <source>No applied run of the automatic tuning is saved for the axes of %1.</source>
        <translation>%1 の軸について保存された自動調整の適用済み実行はありません。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::AutoTuneResultPage</name>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="35" />
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="49" />
        <source>Figure</source>
        <translation>項目</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="49" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="58" />
        <location filename="../app/gui/AutoTuneUndo.cpp" line="130" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="58" />
        <source>Before</source>
        <translation>適用前</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="58" />
        <source>After</source>
        <translation>適用後</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="300" />
        <source>Saved as session %1.</source>
        <translation>セッション %1 として保存しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="301" />
        <source>The session is saved to the store when one is open.</source>
        <translation>ストアが開いていればセッションを保存します。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="305" />
        <source>The run could not start: %1.
Nothing was changed.</source>
        <translation>実行を開始できませんでした: %1。
何も変更していません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="307" />
        <source>%1: %2
RESTORING THE PARAMETERS FAILED: check the drive's parameters.</source>
        <translation>%1: %2
パラメータを元に戻せませんでした: サーボアンプのパラメータを確認してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="308" />
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="311" />
        <source>Aborted</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="308" />
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="311" />
        <source>Refused</source>
        <translation>拒否</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="310" />
        <source>%1: %2
Nothing was changed: every parameter was restored and read back equal.</source>
        <translation>%1: %2
何も変更していません: すべてのパラメータを元に戻し、読み出して一致を確認しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="317" />
        <source>Dry run finished: every parameter was restored; the values below were not applied.</source>
        <translation>試行が完了しました: すべてのパラメータを元に戻しました。以下の値は適用していません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="318" />
        <source>Applied: the parameters below are written and read back equal.</source>
        <translation>適用しました: 以下のパラメータを書き込み、読み出して一致を確認しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="332" />
        <source>Phase margin (re-measured)</source>
        <translation>位相余裕 (再測定)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="332" />
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="333" />
        <source>Gain margin (re-measured)</source>
        <translation>ゲイン余裕 (再測定)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="333" />
        <source>%1 dB</source>
        <translation>%1 dB</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="334" />
        <source>Velocity bandwidth (−3 dB)</source>
        <translation>速度ループ帯域 (−3 dB)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="334" />
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="335" />
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="335" />
        <source>Position bandwidth (−3 dB)</source>
        <translation>位置ループ帯域 (−3 dB)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="336" />
        <source>Settling time of the move</source>
        <translation>移動の整定時間</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="337" />
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="337" />
        <source>not settled within the record</source>
        <translation>記録内で整定せず</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="339" />
        <source>Peak following error</source>
        <translation>最大位置偏差</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="340" />
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="341" />
        <source>%1 mrad</source>
        <translation>%1 mrad</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="343" />
        <source>Motion time of the sequence</source>
        <translation>全手順の動作時間</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="343" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="344" />
        <source>Parameters it would apply (not applied):</source>
        <translation>適用される予定のパラメータ (適用していません):</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="345" />
        <source>Parameters applied (old → new):</source>
        <translation>適用したパラメータ (変更前 → 変更後):</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="63" />
        <source>Figures and parameters</source>
        <translation>結果の数値とパラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="77" />
        <source>Resonance map over the travel</source>
        <translation>ストローク上の共振マップ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="93" />
        <source>Amplitude map</source>
        <translation>振幅マップ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="126" />
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="126" />
        <source>First resonance</source>
        <translation>第 1 共振周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="126" />
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="193" />
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="194" />
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="135" />
        <source>first resonance (labels: frequency, height above the baseline)</source>
        <translation>第 1 共振 (ラベル: 周波数、基準線からの高さ)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="143" />
        <source>%1 Hz, %2 dB</source>
        <translation>%1 Hz、%2 dB</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="158" />
        <source>Position
[%1]</source>
        <translation>位置
[%1]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="158" />
        <source>First resonance
[Hz]</source>
        <translation>第 1 共振
[Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="159" />
        <source>Height
[dB]</source>
        <translation>高さ
[dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="159" />
        <source>Phase margin
[°]</source>
        <translation>位相余裕
[°]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="159" />
        <source>Gain margin
[dB]</source>
        <translation>ゲイン余裕
[dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="160" />
        <source>Velocity bandwidth
[Hz]</source>
        <translation>速度ループ帯域
[Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="160" />
        <source>Position bandwidth
[Hz]</source>
        <translation>位置ループ帯域
[Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="161" />
        <source>Predicted phase
margin [°]</source>
        <translation>予測位相余裕
[°]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="161" />
        <source>Predicted gain
margin [dB]</source>
        <translation>予測ゲイン余裕
[dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="175" />
        <source>none in the band</source>
        <translation>帯域内になし</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="193" />
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="194" />
        <source>Frequency</source>
        <translation>周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="193" />
        <source>Multisine peak</source>
        <translation>マルチサイン振幅</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="193" />
        <source>% of rated torque</source>
        <translation>定格トルク比 %</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="194" />
        <source>Closed velocity loop |T|</source>
        <translation>速度閉ループ |T|</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="194" />
        <source>dB</source>
        <translation>dB</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="223" />
        <source>designed from %1 %</source>
        <translation>設計に使用: %1 %</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="228" />
        <source>linear</source>
        <translation>線形</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="227" />
        <source>non-linear</source>
        <translation>非線形</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="229" />
        <source>not compared</source>
        <translation>比較なし</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="234" />
        <source>%1 % of rated torque</source>
        <translation>定格トルクの %1 %</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="235" />
        <source>non-linear lines</source>
        <translation>非線形の周波数線</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="242" />
        <source>%1 of %2 compared lines non-linear (a line is non-linear when two amplitudes differ by more than %3 combined standard errors). Peak torque of the move with the running gains: %4 % of rated torque; designed from the amplitude %5 % of rated torque.</source>
        <translation>比較した %2 本のうち %1 本の周波数線が非線形 (2 つの振幅の差が合成標準誤差の %3 倍を超える線を非線形とします)。現在のゲインでの移動のピークトルク: 定格トルクの %4 %。設計に使った振幅: 定格トルクの %5 %。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="321" />
        <source>Over %1 positions: the figures are the worst position's; every position is in the resonance map's table.</source>
        <translation>%1 位置で調整: 数値は最も悪い位置のものです。各位置の値は共振マップの表にあります。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="58" />
        <location filename="../app/gui/AutoTuneUndo.cpp" line="133" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="105" />
        <source>Undo anyway…</source>
        <translation>それでも元に戻す…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="108" />
        <source>Undo…</source>
        <translation>元に戻す…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="110" />
        <source>Write back the values the parameters had before the run</source>
        <translation>実行前のパラメータ値を書き戻します</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneResultPage.cpp" line="353" />
        <source>Undo is not offered: %1</source>
        <translation>元に戻すことはできません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="52" />
        <location filename="../app/gui/AutoTuneUndo.cpp" line="145" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="81" />
        <source>Reading the parameters' units failed (%1): values are shown in SI units.</source>
        <translation>パラメータの単位の読み出しに失敗しました (%1): 値はSI単位で表示します。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="118" />
        <source>Undo the automatic tuning anyway</source>
        <translation>自動調整をそれでも元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="118" />
        <source>Undo the automatic tuning</source>
        <translation>自動調整を元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="122" />
        <source>Undo writes back the values the parameters of axis %1 had before the run, all in one write, and reads them back. Nothing moves. These parameters change:</source>
        <translation>元に戻すと、軸 %1 のパラメータを実行前の値に一度の書き込みで書き戻し、読み出して確認します。軸は動きません。変更するパラメータ:</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="130" />
        <source>Applied by the run</source>
        <translation>実行で適用した値</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="132" />
        <source>On the drive now</source>
        <translation>現在のサーボアンプの値</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="133" />
        <source>→ Before the run (written)</source>
        <translation>→ 実行前の値 (書き込む値)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="156" />
        <source>Changed after the run applied it: Undo anyway overwrites this value</source>
        <translation>実行で適用した後に変更されています: それでも元に戻すとこの値を上書きします</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="169" />
        <source>The drive no longer holds what the run applied for %1 (marked red): someone or something changed it after the run. Undo anyway overwrites that later change with the value before the run.</source>
        <translation>%1 (赤で表示) のサーボアンプの値は、実行で適用した値ではありません: 実行後に変更されています。それでも元に戻すと、その後の変更を実行前の値で上書きします。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="175" />
        <source>Overwrite the later change of %1</source>
        <translation>%1 のその後の変更を上書きする</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="182" />
        <source>Undo anyway</source>
        <translation>それでも元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="182" />
        <source>Undo</source>
        <translation>元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="197" />
        <source>Undoing: writing the values before the run and reading them back…</source>
        <translation>元に戻しています: 実行前の値を書き込み、読み出しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="200" />
        <source>Automatic tuning of axis %1: undo%2</source>
        <translation>軸 %1 の自動調整: 元に戻す%2</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="200" />
        <source> (anyway)</source>
        <translation> (上書きを承認)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="225" />
        <source>%1: %2 → %3 %4</source>
        <translation>%1: %2 → %3 %4</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/AutoTuneUndo.cpp" line="227" />
        <source>Undone: %n parameter(s) written back to the values before the run and read back equal.</source>
        <translation>
            <numerusform>元に戻しました: %n 個のパラメータを実行前の値に書き戻し、読み出して一致を確認しました。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="241" />
        <source>Undo refused, nothing written: %1 is %2 %3 on the drive, not the %4 %3 the run applied. It was changed after the run, and undoing would overwrite that change.</source>
        <translation>元に戻すことを拒否しました (何も書き込んでいません): サーボアンプの %1 は %2 %3 で、実行で適用した %4 %3 ではありません。実行後に変更されており、元に戻すとその変更を上書きします。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="244" />
        <source>Also changed: %1.</source>
        <translation>他に変更されたもの: %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="245" />
        <source>Undo anyway… overwrites it after a second confirmation.</source>
        <translation>「それでも元に戻す…」は、もう一度確認した後に上書きします。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="250" />
        <source>Undo refused, nothing written: %1</source>
        <translation>元に戻すことを拒否しました (何も書き込んでいません): %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneUndo.cpp" line="251" />
        <source>Undo failed: %1
Read the axis's parameters to see what the drive holds.</source>
        <translation>元に戻せませんでした: %1
軸のパラメータを読み出して、サーボアンプの値を確認してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="147" />
        <source>An earlier run: session %1.</source>
        <translation>以前の実行: セッション %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="149" />
        <source>Session %1: %2</source>
        <translation>セッション %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="155" />
        <source>Session %1 applied these parameters to axis %2. Undo writes back the values they had before it, in one write, read back, when the drive still holds what the run applied.</source>
        <translation>セッション %1 は軸 %2 にこれらのパラメータを適用しました。サーボアンプが実行の適用した値をまだ保持していれば、「元に戻す」は実行前の値を一度に書き戻し、読み戻して確認します。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneEarlier.cpp" line="161" />
        <source>Parameters the run applied (before → applied):</source>
        <translation>実行が適用したパラメータ (実行前 → 適用値):</translation>
    </message>
</context>
<context>
    <name>axistune::gui::AutoTuneRunPage</name>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="387" />
        <source>Running the sequence</source>
        <translation>手順を実行中</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="388" />
        <source>Abort stops the motion at once; every parameter the run wrote is restored and read back.</source>
        <translation>中止すると動作をすぐに止め、実行中に書き込んだすべてのパラメータを元に戻して読み出します。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="393" />
        <source>Step</source>
        <translation>手順</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="393" />
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="409" />
        <source>What each finished step measured, what it chose and the rule.</source>
        <translation>完了した各手順の測定値、選んだ値、規則。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="418" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="430" />
        <source>Result &gt;</source>
        <translation>結果 &gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="466" />
        <location filename="../app/gui/AutoTuneWizard.cpp" line="510" />
        <source>waiting</source>
        <translation>待機中</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="469" />
        <source>Axis %1, style %2, time budget %3 s%4.</source>
        <translation>軸 %1、スタイル %2、時間予算 %3 s%4。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="475" />
        <source>, dry run</source>
        <translation>、試行のみ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="488" />
        <source>Automatic tuning of axis %1 started</source>
        <translation>軸 %1 の自動調整を開始しました</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="499" />
        <source>Aborting: stopping the motion and restoring every parameter…</source>
        <translation>中止中: 動作を止め、すべてのパラメータを元に戻しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="511" />
        <source>running…</source>
        <translation>実行中…</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="518" />
        <source>done</source>
        <translation>完了</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="525" />
        <source> (%1 s of motion)</source>
        <translation> (動作 %1 s)</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="526" />
        <source>Measured: %1</source>
        <translation>測定: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="527" />
        <source>Chosen: %1</source>
        <translation>選択: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="528" />
        <source>Rule: %1</source>
        <translation>規則: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="537" />
        <source>no answer from the drive</source>
        <translation>サーボアンプから応答がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="539" />
        <source>The run could not start: %1. Nothing was changed.</source>
        <translation>実行を開始できませんでした: %1。何も変更していません。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="544" />
        <source>aborted</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="544" />
        <source>refused</source>
        <translation>拒否</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="546" />
        <source>every parameter restored and read back equal</source>
        <translation>すべてのパラメータを元に戻し、読み出して一致を確認</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="547" />
        <source>RESTORING THE PARAMETERS FAILED: check the drive</source>
        <translation>パラメータを元に戻せませんでした: サーボアンプを確認してください</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="549" />
        <source>Aborted (%1): %2.</source>
        <translation>中止 (%1): %2。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="549" />
        <source>Refused (%1): %2.</source>
        <translation>拒否 (%1): %2。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="553" />
        <source>Finished (dry run): every parameter restored; see the result.</source>
        <translation>完了 (試行のみ): すべてのパラメータを元に戻しました。結果を参照してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="554" />
        <source>Finished: the parameters are applied; see the result.</source>
        <translation>完了: パラメータを適用しました。結果を参照してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="476" />
        <source> Over the travel: %1 positions.</source>
        <translation> ストローク全体で %1 位置。</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="479" />
        <source> Amplitude map at %1 % of rated torque.</source>
        <translation> 振幅マップ: 定格トルクの %1 %。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::AutoTuneWizard</name>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="101" />
        <source>1. Safety envelope</source>
        <translation>1. 安全範囲</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="103" />
        <source>2. Current loop</source>
        <translation>2. 電流ループ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="105" />
        <source>3. Adaptive frequency response</source>
        <translation>3. 適応周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="107" />
        <source>4. Notch filters</source>
        <translation>4. ノッチフィルタ</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="109" />
        <source>5. Velocity PI</source>
        <translation>5. 速度PI</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="111" />
        <source>6. Position gain and feedforward</source>
        <translation>6. 位置ゲインとフィードフォワード</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="113" />
        <source>7. Move evaluation</source>
        <translation>7. 移動評価</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="115" />
        <source>8. Verify</source>
        <translation>8. 検証</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="117" />
        <source>9. Apply or roll back</source>
        <translation>9. 適用または元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/AutoTuneWizard.cpp" line="623" />
        <source>Automatic tuning</source>
        <translation>自動調整</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CircleRunner</name>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="91" />
        <source>Not connected: circle tests need a connection to a machine.</source>
        <translation>未接続: 円弧補間テストには機械との接続が必要です。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="154" />
        <source>Circle %1 failed: %2</source>
        <translation>円弧 %1 が失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="160" />
        <source>Circle %1 could not be evaluated: %2</source>
        <translation>円弧 %1 を評価できませんでした: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="178" />
        <source>Aborted by the operator after %1 of %2 circles.</source>
        <translation>%2 回中 %1 回の円弧の後、作業者により中止されました。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="130" />
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="146" />
        <source>Circle %1 of %2</source>
        <translation>円弧 %1 / %2</translation>
    </message>
</context>
<context>
    <name>axistune::gui::ConnectDialog</name>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="160" />
        <location filename="../app/gui/ConnectDialog.cpp" line="178" />
        <source>Connect</source>
        <translation>接続</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="163" />
        <source>Address form: %1</source>
        <translation>アドレスの形式: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="166" />
        <source>%1:</source>
        <translation>%1:</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="170" />
        <source>Browse…</source>
        <translation>参照…</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="176" />
        <source>Noise seed:</source>
        <translation>ノイズのシード:</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="231" />
        <source>Choose a connection.</source>
        <translation>接続先を選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="240" />
        <source>Enter %1.</source>
        <translation>%1 を入力してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="326" />
        <source>Connecting to %1 …</source>
        <translation>%1 に接続中…</translation>
    </message>
    <message>
        <location filename="../app/gui/ConnectDialog.cpp" line="342" />
        <source>The connection failed: %1</source>
        <translation>接続に失敗しました: %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CurrentLoopDesignPage</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="321" />
        <source>Current loop: design</source>
        <translation>電流ループ: 設計</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="323" />
        <source>For each PI ratio α the gains with the shortest rise time inside the dead-time stability boundary (gain margin), the voltage envelope and the overshoot limit; α* has the shortest rise time of all.</source>
        <translation>各 PI率 α について、むだ時間の安定限界 (ゲイン余裕)、電圧の包絡線、オーバーシュート制限の内側で立ち上がり時間が最短となるゲイン; α* はその中で最も立ち上がり時間が短い α です。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="330" />
        <source>Show the boundaries of every α</source>
        <translation>すべての α の境界を表示</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="332" />
        <source>Chosen α:</source>
        <translation>選択した α:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="340" />
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="353" />
        <source>k_p</source>
        <translation>k_p</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="340" />
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="353" />
        <source>V/A</source>
        <translation>V/A</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="340" />
        <source>k_i</source>
        <translation>k_i</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="340" />
        <source>V/(A·s)</source>
        <translation>V/(A·s)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="344" />
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="346" />
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="344" />
        <source>Rise time 10–90 %</source>
        <translation>立ち上がり時間 10–90 %</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="346" />
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="355" />
        <source>k_p [V/A]</source>
        <translation>k_p [V/A]</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="346" />
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="355" />
        <source>k_i [V/(A·s)]</source>
        <translation>k_i [V/(A·s)]</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="346" />
        <source>Rise time [µs]</source>
        <translation>立ち上がり時間 [µs]</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="346" />
        <source>Overshoot [%]</source>
        <translation>オーバーシュート [%]</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="347" />
        <source>Active constraints</source>
        <translation>有効な制約</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="353" />
        <source>Current |i|</source>
        <translation>電流 |i|</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="355" />
        <source>Current [A]</source>
        <translation>電流 [A]</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="355" />
        <source>Factor</source>
        <translation>係数</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="358" />
        <source>Rise time against α</source>
        <translation>α に対する立ち上がり時間</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="359" />
        <source>α table</source>
        <translation>α の表</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="360" />
        <source>Gain schedule</source>
        <translation>ゲインスケジュール</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="388" />
        <source>Designing…</source>
        <translation>設計中…</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="429" />
        <source>The design failed: %1</source>
        <translation>設計に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="446" />
        <source> (optimum α*)</source>
        <translation> (最適 α*)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="453" />
        <source>infeasible</source>
        <translation>実現不可</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="456" />
        <source>Rise time of the optimum per α</source>
        <translation>α ごとの最適点の立ち上がり時間</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="457" />
        <source>α* = %1</source>
        <translation>α* = %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="459" />
        <source>Optimum α* = %1: k_p = %2 V/A, k_i = %3 V/(A·s), rise time %4 µs (delay-free design model).</source>
        <translation>最適 α* = %1: k_p = %2 V/A、k_i = %3 V/(A·s)、立ち上がり時間 %4 µs (むだ時間なしの設計モデル)。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="476" />
        <source>Stability boundary (gain margin %1 dB)</source>
        <translation>安定限界 (ゲイン余裕 %1 dB)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="486" />
        <source>Voltage envelope α = %1</source>
        <translation>電圧の包絡線 α = %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="488" />
        <source>Overshoot %1 % α = %2</source>
        <translation>オーバーシュート %1 % α = %2</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="493" />
        <source>α = %1: k_p %2 V/A, k_i %3 V/(A·s)</source>
        <translation>α = %1: k_p %2 V/A、k_i %3 V/(A·s)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="509" />
        <source>k_p over current (k_i in the same ratio)</source>
        <translation>電流に対する k_p (k_i も同じ比率)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CurrentLoopMotorPage</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="70" />
        <source>Current loop: motor data</source>
        <translation>電流ループ: モータデータ</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="71" />
        <source>Enter the motor data or read them from the drive's motor parameters. Maximum current and maximum voltage must use the same convention (both peak or both rms): only their ratio enters the voltage constraint.</source>
        <translation>モータデータを入力するか、サーボアンプのモータパラメータから読み出してください。最大電流と最大電圧は同じ表し方 (両方ピーク値または両方実効値) にしてください: 電圧制約にはその比だけが入ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="78" />
        <source>Read from drive</source>
        <translation>サーボアンプから読み出し</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="80" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="83" />
        <source>From profile</source>
        <translation>プロファイルから</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="85" />
        <source>The motor model of this axis in the machine's profile (saved by an earlier current-loop session or imported)</source>
        <translation>機械プロファイルにあるこの軸のモータモデル（以前の電流ループのセッションで保存したもの、またはインポートしたもの）</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="95" />
        <source>Motor</source>
        <translation>モータ</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="104" />
        <source> V(rms)/1000 min⁻¹</source>
        <translation> V(rms)/1000 min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="105" />
        <source> min⁻¹</source>
        <translation> min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="106" />
        <source>Armature resistance R_a:</source>
        <translation>電機子抵抗 R_a:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="107" />
        <source>q-axis inductance L_q:</source>
        <translation>q 軸インダクタンス L_q:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="108" />
        <source>Maximum current I_max:</source>
        <translation>最大電流 I_max:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="109" />
        <source>Maximum voltage V_max:</source>
        <translation>最大電圧 V_max:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="110" />
        <source>Inductance drop at I_max δ:</source>
        <translation>I_max でのインダクタンス低下 δ:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="111" />
        <source>Rated current (0: not given):</source>
        <translation>定格電流 (0: 指定なし):</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="112" />
        <source>Back-EMF constant, line-to-line (0: not given):</source>
        <translation>誘起電圧定数、線間 (0: 指定なし):</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="113" />
        <source>Contouring speed:</source>
        <translation>輪郭加工速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="115" />
        <source>Design</source>
        <translation>設計</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="121" />
        <source>Dead time τ of the design:</source>
        <translation>設計のむだ時間 τ:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="122" />
        <source>Gain margin:</source>
        <translation>ゲイン余裕:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="123" />
        <source>Step overshoot limit:</source>
        <translation>ステップ応答のオーバーシュート制限:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="124" />
        <source>Current ripple of the voltage check (of I_max):</source>
        <translation>電圧チェックの電流リプル (I_max に対する比):</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="173" />
        <source>Reading the motor parameters failed: %1</source>
        <translation>モータパラメータの読み出しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="186" />
        <source>Read from axis %1 of the drive (peak values): maximum current, maximum voltage, rated current, current-loop period %2 µs, dead time %3 µs; the back-EMF constant from the torque constant (k_e = k_t/1.5, amplitude-invariant dq). The drive does not offer R_a, L_q and δ: enter them from the motor data sheet.</source>
        <translation>サーボアンプの軸 %1 から読み出しました (ピーク値): 最大電流、最大電圧、定格電流、電流ループ周期 %2 µs、むだ時間 %3 µs; 誘起電圧定数はトルク定数から (k_e = k_t/1.5、振幅不変の dq 変換)。サーボアンプは R_a、L_q、δ を提供しないため、モータのデータシートから入力してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="153" />
        <source>Not connected: enter the motor data (defaults: the rotary motor of Table 2.2, rms values). Apply needs a connection.</source>
        <translation>未接続: モータデータを入力してください (初期値: 表 2.2 の回転形モータ、実効値)。適用には接続が必要です。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="202" />
        <source>No machine profile: open a store and connect to (or choose) a machine first.</source>
        <translation>機械プロファイルがありません。先にストアを開き、機械に接続して（または機械を選んで）ください。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="209" />
        <source>The profile of machine %1 has no motor model for axis %2: enter the data, or save a current-loop session first.</source>
        <translation>機械 %1 のプロファイルに軸 %2 のモータモデルがありません。データを入力するか、先に電流ループのセッションを保存してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="212" />
        <source>The profile of machine %1 could not be read: %2</source>
        <translation>機械 %1 のプロファイルを読めませんでした: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="227" />
        <source>R_a</source>
        <translation>R_a</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="228" />
        <source>L_q</source>
        <translation>L_q</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="229" />
        <source>δ</source>
        <translation>δ</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="230" />
        <source>I_max</source>
        <translation>I_max</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="231" />
        <source>V_max</source>
        <translation>V_max</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="232" />
        <source>rated current</source>
        <translation>定格電流</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="233" />
        <source>back-EMF constant</source>
        <translation>誘起電圧定数</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="236" />
        <source>Taken from the profile of machine %1, axis %2: %3.</source>
        <translation>機械 %1、軸 %2 のプロファイルから取得: %3。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="238" />
        <source>Not in the profile, kept as shown: %1.</source>
        <translation>プロファイルにないため表示のまま: %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="278" />
        <source>Back-EMF check at the contouring speed %1 min⁻¹: %2 V(rms, line-to-line) = %3 V peak per phase, %4 % of V_max = %5 V (peak comparison; with rms values %6 %). The design neglects the back-EMF, which holds when it is small against V_max.</source>
        <translation>輪郭加工速度 %1 min⁻¹ での誘起電圧の確認: %2 V (実効値、線間) = 相あたりピーク %3 V、V_max = %5 V の %4 % (ピーク値で比較; 実効値では %6 %)。設計は誘起電圧を無視しており、これは V_max に比べて小さいときに成り立ちます。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="288" />
        <source>No back-EMF constant given: the back-EMF at the contouring speed is not checked.</source>
        <translation>誘起電圧定数の指定なし: 輪郭加工速度での誘起電圧は確認しません。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardPages.cpp" line="291" />
        <source>Not usable: %1</source>
        <translation>使用できません: %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CurrentLoopSavePage</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="38" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="40" />
        <source>The session holds the motor data and settings, the α table, the chosen α and gains with the rise time, the gain schedule, the predicted step responses, what was applied with its journal, the read-back, and the current step measured on the drive with its comparison.</source>
        <translation>セッションには、モータデータと設定、α の表、選んだ α とゲインと立ち上がり時間、ゲインスケジュール、予測したステップ応答、適用した内容とその履歴、読み出し値、サーボアンプで測定した電流ステップとその比較が保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="60" />
        <source>α = %1, k_p = %2 V/A, k_i = %3 V/(A·s), rise time %4 µs (delay-free design).</source>
        <translation>α = %1、k_p = %2 V/A、k_i = %3 V/(A·s)、立ち上がり時間 %4 µs (むだ時間なしの設計)。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="66" />
        <source>Not connected: the gains were not applied.</source>
        <translation>未接続: ゲインは適用されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="68" />
        <source>Not applied: the proposal is kept in the session.</source>
        <translation>未適用: 提案はセッションに保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="70" />
        <source>Applied to axis %1 and read back.</source>
        <translation>軸 %1 に適用し、読み出して確認しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="72" />
        <source>Measured current step of %1 A: rise time %2 µs (predicted %3 µs), overshoot %4 % (predicted %5 %); largest difference %6 % of the step.</source>
        <translation>%1 A の電流ステップの実測: 立ち上がり時間 %2 µs (予測 %3 µs)、オーバーシュート %4 % (予測 %5 %)。最大差はステップの %6 %。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="80" />
        <source>Saved as session %1.</source>
        <translation>セッション %1 として保存しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="81" />
        <source>The session was not saved (no store open).</source>
        <translation>セッションは保存されませんでした (データベースが開かれていません)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CurrentLoopStepPage</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="73" />
        <source>Current loop: step responses</source>
        <translation>電流ループ: ステップ応答</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="74" />
        <source>The delay-free design model against the prediction with the drive's current-loop period (zero-order hold) and dead time; a current step is measured on the drive before and after applying.</source>
        <translation>むだ時間なしの設計モデルと、サーボアンプの電流ループ周期 (0 次ホールド) とむだ時間を含めた予測の比較。適用の前と後にサーボアンプで電流ステップを測定します。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="80" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="80" />
        <source>Current / command</source>
        <translation>電流 / 指令</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="86" />
        <source>Current step on the drive, before and after applying</source>
        <translation>適用前後のサーボアンプでの電流ステップ</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="89" />
        <source>Measure a current step (velocity loop open, then the axis holds its position)</source>
        <translation>電流ステップを測定する (速度ループ開放、その後は軸が位置を保持)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="98" />
        <source>Step of the q-axis current command:</source>
        <translation>q 軸電流指令のステップ:</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="104" />
        <source>Recording (the step comes 10 % in):</source>
        <translation>記録時間 (ステップは 10 % の時点):</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="136" />
        <source>Delay-free design</source>
        <translation>むだ時間なしの設計</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="137" />
        <source>Prediction: period %1 µs + dead time %2 µs</source>
        <translation>予測: 周期 %1 µs + むだ時間 %2 µs</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="143" />
        <source>Delay-free: %1. With the delay: %2.</source>
        <translation>むだ時間なし: %1。むだ時間あり: %2。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="156" />
        <source>Default %1 A: at most %2 % of I_max, and the voltage before the current can respond, (α k_p + (d + 1)·k_i T)·i* = %3 V with d dead-time periods, stays within %4 % of V_max (%5 V), so no voltage clamp acts and the inductance falls by only δ·i*/I_max = %6 %.</source>
        <translation>既定値 %1 A: I_max の %2 % 以下で、電流が応答する前の電圧 (α k_p + (d + 1)·k_i T)·i* = %3 V (d はむだ時間の周期数) が V_max (%5 V) の %4 % 以内に収まるため、電圧クランプは働かず、インダクタンスの低下は δ·i*/I_max = %6 % にとどまります。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="209" />
        <source>A q-axis current step of %1 A recorded for %2 ms, twice: now with the gains the drive holds, and after applying the proposed ones. The velocity and position loops are open while it lasts: the motor accelerates freely, then the axis holds its position again.</source>
        <translation>q 軸電流を %1 A ステップさせて %2 ms 記録します。これを 2 回、現在のサーボアンプのゲインで今、提案したゲインを適用した後にもう一度行います。その間は速度ループと位置ループを開放するため、モータは自由に加速し、その後軸は再び位置を保持します。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="167" />
        <source>Reading the drive's limits…</source>
        <translation>サーボアンプの上限を読み取り中…</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="182" />
        <source>&lt;span style='color:#b00000'&gt;The drive does not state its current-step limits: %1&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;サーボアンプが電流ステップの上限を示していません: %1&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="194" />
        <source>The drive refuses a step above %1 A, a recording beyond %2 ms and a step that would take the motor beyond %3 rad/s.</source>
        <translation>サーボアンプは %1 A を超えるステップ、%2 ms を超える記録、モータが %3 rad/s を超えるステップを拒否します。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CurrentLoopVerifyPage</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="232" />
        <source>Current loop: verification</source>
        <translation>電流ループ: 検証</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="233" />
        <source>The gains read back from the drive, the step predicted with them (period and dead time of the drive) and the design, against the current step measured on the drive.</source>
        <translation>サーボアンプから読み出したゲイン、そのゲインで予測したステップ応答 (サーボアンプの周期とむだ時間) と設計を、サーボアンプで測定した電流ステップと比較します。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="238" />
        <source>Current / command</source>
        <translation>電流 / 指令</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="238" />
        <source>Time since the step</source>
        <translation>ステップからの時間</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="265" />
        <source>Reading back failed: %1</source>
        <translation>読み出しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="252" />
        <source>Not connected: nothing to verify.</source>
        <translation>未接続: 検証するものはありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="314" />
        <source>Prediction with the read-back gains (period + dead time)</source>
        <translation>読み出したゲインでの予測 (周期 + むだ時間)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="319" />
        <source>Read back: k_p %1 V/A, k_i %2 V/(A·s), α %3 — %4.</source>
        <translation>読み出し値: k_p %1 V/A、k_i %2 V/(A·s)、α %3 — %4。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="325" />
        <source>Not applied: the drive kept its own gains, and the measurement is of those.</source>
        <translation>未適用: サーボアンプは元のゲインのままで、測定はそのゲインでのものです。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="327" />
        <source>Measured before applying (gains before)</source>
        <translation>適用前の実測 (適用前のゲイン)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="330" />
        <source>Measured on the drive (%1 A step)</source>
        <translation>サーボアンプでの実測 (%1 A ステップ)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="334" />
        <source>Predicted step with them: %1.</source>
        <translation>そのゲインで予測したステップ応答: %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="335" />
        <source>No measured current step: %1</source>
        <translation>電流ステップの実測なし: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="336" />
        <source>No current step was measured (not chosen on the step page).</source>
        <translation>電流ステップは測定していません (ステップ応答のページで選択されていません)。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="356" />
        <source>The measured step agrees with the delay-inclusive prediction within %1 % of the step.</source>
        <translation>実測したステップ応答は、むだ時間を含む予測とステップの %1 % 以内で一致しています。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="358" />
        <source>The measured step differs from the delay-inclusive prediction by more than %1 % of the step: check R_a, L_q and the dead time, or use a smaller step.</source>
        <translation>実測したステップ応答は、むだ時間を含む予測とステップの %1 % を超えて異なります: R_a、L_q とむだ時間を確認するか、ステップを小さくしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="361" />
        <source>Current step of %1 A measured on the drive (%2 samples at %3 µs):</source>
        <translation>サーボアンプで測定した %1 A の電流ステップ (%3 µs 間隔で %2 点):</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="365" />
        <source>• measured: 10–90 % rise time %1 µs, overshoot %2 %</source>
        <translation>• 実測: 10–90 % 立ち上がり時間 %1 µs、オーバーシュート %2 %</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="367" />
        <source>• design (delay-free): rise time %1 µs, overshoot %2 %</source>
        <translation>• 設計 (むだ時間なし): 立ち上がり時間 %1 µs、オーバーシュート %2 %</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="368" />
        <source>• prediction (period + dead time, read-back gains): rise time %1 µs, overshoot %2 %</source>
        <translation>• 予測 (周期 + むだ時間、読み出したゲイン): 立ち上がり時間 %1 µs、オーバーシュート %2 %</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="371" />
        <source>• measured before applying (gains before): rise time %1 µs, overshoot %2 %</source>
        <translation>• 適用前の実測 (適用前のゲイン): 立ち上がり時間 %1 µs、オーバーシュート %2 %</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="373" />
        <source>Measured − predicted: rise time %1 µs, overshoot %2 percentage points; largest difference %3 % of the step, rms %4 % over %5 samples.</source>
        <translation>実測 − 予測: 立ち上がり時間 %1 µs、オーバーシュート %2 ポイント。最大差はステップの %3 %、%5 点での rms は %4 %。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="381" />
        <source>The voltage clamp acted in %1 current periods: the measured step is not the linear loop the prediction describes; use a smaller step.</source>
        <translation>電圧クランプが電流制御周期 %1 回で働きました: 実測は予測が表す線形なループではありません。ステップを小さくしてください。</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="256" />
        <source>Reading back…</source>
        <translation>読み出し中…</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="312" />
        <source>Design (delay-free, proposed gains)</source>
        <translation>設計 (むだ時間なし、提案ゲイン)</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="323" />
        <source>as proposed</source>
        <translation>提案どおり</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizardStep.cpp" line="323" />
        <source>NOT as proposed</source>
        <translation>提案と異なる</translation>
    </message>
</context>
<context>
    <name>axistune::gui::CurrentLoopWizard</name>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="87" />
        <source>Current loop</source>
        <translation>電流ループ</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="116" />
        <source>The current step before applying failed: %1</source>
        <translation>適用前の電流ステップ応答が失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="133" />
        <source>The current step after applying failed: %1</source>
        <translation>適用後の電流ステップ応答が失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/CurrentLoopWizard.cpp" line="135" />
        <source>the current-loop gains</source>
        <translation>電流ループゲイン</translation>
    </message>
</context>
<context>
    <name>axistune::gui::DriveController</name>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="267" />
        <source>Connection lost: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="324" />
        <source>Connected: %1</source>
        <translation>接続中: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="325" />
        <source>Connection to %1 failed: %2</source>
        <translation>%1 への接続に失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/DriveController.cpp" line="329" />
        <source>Not connected</source>
        <translation>未接続</translation>
    </message>
</context>
<context>
    <name>axistune::gui::FrfConfigPage</name>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="289" />
        <source>Method and band</source>
        <translation>方式と帯域</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="290" />
        <source>How the axis is excited and which frequencies are measured.</source>
        <translation>軸の加振方法と測定する周波数。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="331" />
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="332" />
        <source>Motion time of all passes, at most:</source>
        <translation>全パスの動作時間の上限:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="413" />
        <source>Multi-sweep sine stream (valid up to the trace rate)</source>
        <translation>複数回掃引の正弦波ストリーム (トレース周波数まで有効)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="414" />
        <source>Conventional sine stream (valid up to half the trace rate)</source>
        <translation>従来の正弦波ストリーム (トレース周波数の半分まで有効)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="415" />
        <source>PRBS with Welch averaging and coherence (up to half the trace rate)</source>
        <translation>PRBS、Welch 平均とコヒーレンス (トレース周波数の半分まで)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="416" />
        <source>Multisine, all lines at once (valid up to the trace rate)</source>
        <translation>マルチサイン、全周波数を同時に (トレース周波数まで有効)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="295" />
        <source>Method:</source>
        <translation>方式:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="306" />
        <location filename="../app/gui/FrfWizardPages.cpp" line="313" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="307" />
        <source>Lowest frequency:</source>
        <translation>最低周波数:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="314" />
        <source>Highest frequency:</source>
        <translation>最高周波数:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="319" />
        <source>Frequencies (log-spaced):</source>
        <translation>周波数点数 (対数間隔):</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="320" />
        <source>Adaptive: excite the lines not yet valid again</source>
        <translation>適応測定: まだ有効でない周波数線を再加振する</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="321" />
        <source>After the first multisine, the lines not yet valid are excited again (shaped by 1/|H| and their noise, more periods where needed) until every line is valid or the time budget is spent.</source>
        <translation>最初のマルチサインの後、まだ有効でない周波数線を再加振します (1/|H| とノイズで整形し、必要な所では周期数を増やす)。全線が有効になるか時間予算を使い切るまで続けます。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="507" />
        <source>&lt;span style='color:#b00000'&gt;The first pass takes %1 s of motion, more than the time budget of %2 s.&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;最初のパスの動作時間は %1 s で、時間予算 %2 s を超えます。&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="512" />
        <source>Estimated motion time of the first pass: %1 s (settling included); with the passes after it at most %2 s.</source>
        <translation>最初のパスの推定動作時間: %1 s (整定を含む)。後続のパスを含めて最大 %2 s。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="517" />
        <source>Estimated motion time: %1 s (settling included).</source>
        <translation>推定動作時間: %1 s (整定時間を含む)。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="480" />
        <location filename="../app/gui/FrfWizardPages.cpp" line="502" />
        <source>&lt;span style='color:#b00000'&gt;The drive would refuse this test: %1&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;サーボアンプはこのテストを拒否します: %1&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="456" />
        <source>Trace rate fs = %1 Hz. The multi-sweep and multisine methods measure up to fs; the conventional sine stream and PRBS only up to fs/2 = %2 Hz (points above are marked not valid).</source>
        <translation>トレース周波数 fs = %1 Hz。複数回掃引とマルチサインは fs まで測定できます。従来の正弦波ストリームと PRBS は fs/2 = %2 Hz までです (それより上の点は無効と表示)。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="464" />
        <source>The trace rate of the drive is unknown.</source>
        <translation>サーボアンプのトレース周波数が不明です。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="483" />
        <source>Estimating the motion time…</source>
        <translation>動作時間を推定中…</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="480" />
        <source>not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="298" />
        <source>Measured quantity:</source>
        <translation>測定する量:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="428" />
        <source>Plant: feedback / drive input</source>
        <translation>プラント: フィードバック / サーボアンプ入力</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="430" />
        <source>Open loop with the running gains: −controller output / drive input</source>
        <translation>現在のゲインでの開ループ: −制御器出力 / サーボアンプ入力</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="446" />
        <source>Trace rate fs = %1 Hz. This drive measures lines below %2 Hz only; the band must end below that.</source>
        <translation>トレース周波数 fs = %1 Hz。このサーボアンプは %2 Hz 未満の周波数線しか測定できません。帯域はそれより下で終わる必要があります。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="454" />
        <source>&lt;span style='color:#b00000'&gt;The drive offers no FRF method on this axis.&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;このサーボアンプはこの軸で周波数応答の測定方法を提供していません。&lt;/span&gt;</translation>
    </message>
</context>
<context>
    <name>axistune::gui::FrfResultPage</name>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="530" />
        <source>Frequency response</source>
        <translation>周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="531" />
        <location filename="../app/gui/FrfWizardPages.cpp" line="615" />
        <source>The measured closed velocity loop, where it is valid, and the resonances found.</source>
        <translation>測定した速度閉ループ (有効な範囲) と、見つかった共振。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="552" />
        <source>Frequency [Hz]</source>
        <translation>周波数 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="552" />
        <source>Peak [dB]</source>
        <translation>ピーク [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="552" />
        <source>Width (−3 dB) [Hz]</source>
        <translation>帯域幅 (−3 dB) [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="553" />
        <location filename="../app/gui/FrfWizardPages.cpp" line="619" />
        <source>Open-loop gain [dB]</source>
        <translation>開ループゲイン [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="600" />
        <source>No frequency response was measured.</source>
        <translation>周波数応答は測定されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="623" />
        <source>Measured</source>
        <translation>測定値</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="626" />
        <source>Analysing…</source>
        <translation>解析中…</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="723" />
        <source>%1 of %2 points valid.</source>
        <translation>%2 点中 %1 点が有効。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="734" />
        <source>Trace rate fs = %1 Hz.</source>
        <translation>トレース周波数 fs = %1 Hz。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="736" />
        <source>No resonance list: %1</source>
        <translation>共振リストなし: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="738" />
        <source>No resonance found in %1.</source>
        <translation>%1 に共振は見つかりませんでした。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/FrfWizardPages.cpp" line="740" />
        <source>%n resonance(s) found in %1:</source>
        <translation>
            <numerusform>%1 に %n 個の共振が見つかりました:</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="751" />
        <source>Only one −3 dB crossing inside the band: twice the half width.</source>
        <translation>帯域内の −3 dB 交差が 1 つだけ: 半値幅の 2 倍。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="604" />
        <location filename="../app/gui/FrfWizardPages.cpp" line="724" />
        <source>the drive input</source>
        <translation>サーボアンプ入力</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="606" />
        <source>The measured plant: feedback per unit of drive input (%1 plus the injection), where it is valid, and the resonances found.</source>
        <translation>測定したプラント: サーボアンプ入力 (%1 + 注入信号) 1 単位あたりのフィードバック、その有効範囲、見つかった共振。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="609" />
        <source>Plant [dB]</source>
        <translation>プラント [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="611" />
        <source>The measured open position loop with the running gains: −controller output / drive input (dimensionless), where it is valid, and the resonances found.</source>
        <translation>現在のゲインで測定した位置ループの開ループ: −制御器出力 / サーボアンプ入力 (無次元)、その有効範囲、見つかった共振。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="613" />
        <source>Open loop |L| [dB]</source>
        <translation>開ループ |L| [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="620" />
        <source>Level of the analysed response [dB]</source>
        <translation>解析した応答のレベル [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="621" />
        <source>Measured plant</source>
        <translation>測定したプラント</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="622" />
        <source>Measured open loop</source>
        <translation>測定した開ループ</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="726" />
        <source>Plant in the feedback's position units per unit of %1 (the configuration's units, e.g. mm per N·m).</source>
        <translation>プラントは %1 の 1 単位あたりのフィードバック位置単位で表します (構成の単位、例: mm/N·m)。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="731" />
        <source>Open position loop, dimensionless (controller output per unit of %1).</source>
        <translation>位置ループの開ループ、無次元 (%1 の 1 単位あたりの制御器出力)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::FrfSafetyPage</name>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="99" />
        <location filename="../app/gui/FrfWizardPages.cpp" line="193" />
        <source>The axis holds velocity 0 in velocity mode while a small torque disturbance is added to the velocity-controller output. The axis vibrates with small amplitude at each test frequency; it does not travel. Abort stops the excitation at once and restores the parameters.</source>
        <translation>軸は速度制御モードで速度 0 を保持し、速度制御器の出力に小さなトルク外乱を加えます。軸は各試験周波数で小さな振幅で振動しますが、移動はしません。中止すると加振は直ちに止まり、パラメータは元に戻ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="112" />
        <source> % of rated torque</source>
        <translation> % (定格トルク比)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="113" />
        <source>Excitation amplitude:</source>
        <translation>加振振幅:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="256" />
        <source>&lt;span style='color:#b00000'&gt;Refused: the drive allows at most %1 % of rated torque.&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;拒否: サーボアンプが許すのは定格トルクの %1 % までです。&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="263" />
        <source>%1 % of rated torque (at most %2 %).</source>
        <translation>定格トルクの %1 % (最大 %2 %)。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="266" />
        <source>%1 % of the rated torque %2 N·m = %3 N·m peak of the injected torque (at most %4 %).</source>
        <translation>定格トルク %2 N·m の %1 % = 注入トルクのピーク %3 N·m (最大 %4 %)。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="246" />
        <source>&lt;span style='color:#b00000'&gt;The drive does not state its amplitude limit: %1&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;サーボアンプが振幅の上限を示していません: %1&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="252" />
        <source>%1 % of rated torque (reading the drive's limit…).</source>
        <translation>定格トルクの %1 % (サーボアンプの上限を読み取り中…)。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="120" />
        <source>Excitation peak:</source>
        <translation>加振ピーク値:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="199" />
        <source> (units of %1)</source>
        <translation> (%1 の単位)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="209" />
        <source>The NC keeps closing its position loop while a small multisine is added to %1, the drive's input, at every servo period. The axis vibrates with small amplitude about where it stands; it does not travel. A following error above the limit or Abort stops the excitation at once, and what AxisTune inserted into the machine is removed.</source>
        <translation>NC が位置ループを閉じたまま、サーボアンプ入力である %1 に小さなマルチサインをサーボ周期ごとに加えます。軸は現在位置の周りで小さな振幅で振動し、移動はしません。位置偏差が制限を超えるか中止すると加振はすぐに止まり、AxisTune が機械に挿入したものは取り除かれます。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="223" />
        <source>&lt;span style='color:#b00000'&gt;The drive states no limit for the peak in the units of %1: no test.&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;サーボアンプが %1 の単位でのピーク値の上限を示していません: 測定できません。&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="227" />
        <source>&lt;span style='color:#b00000'&gt;Refused: the peak must be above 0.&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;拒否: ピーク値は 0 より大きくなければなりません。&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="229" />
        <source>&lt;span style='color:#b00000'&gt;Refused: the drive allows a peak of at most %1 in the units of %2.&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00000'&gt;拒否: サーボアンプが許すピーク値は %2 の単位で最大 %1 です。&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="234" />
        <source>Peak %1 of the injected signal, in the units of %2 (the drive allows at most %3, %4 % of its output limit).</source>
        <translation>注入信号のピーク値 %1 (%2 の単位。サーボアンプが許す最大値は %3、出力制限の %4 %)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::FrfSavePage</name>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="764" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="765" />
        <source>Finish stores the measurement as a session of this machine.</source>
        <translation>完了すると、測定をこの機械のセッションとして保存します。</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="770" />
        <source>e.g. before notch tuning, table empty</source>
        <translation>例: ノッチ調整前、テーブル上は空</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="771" />
        <source>Note:</source>
        <translation>メモ:</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="777" />
        <source>Show the saved session as a document (its Bode plot stays open after Finish)</source>
        <translation>保存したセッションをドキュメントとして表示する（完了後もボード線図が開いたままになります）</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="782" />
        <source>Save and open in the notch wizard</source>
        <translation>保存してノッチフィルタのウィザードで開く</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizardPages.cpp" line="784" />
        <source>Stores the session, then proposes notch filters for the resonances of this measurement.</source>
        <translation>セッションを保存し、この測定の共振に対するノッチフィルタを提案します。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::FrfWizard</name>
    <message>
        <location filename="../app/gui/FrfWizard.cpp" line="44" />
        <source>Frequency response</source>
        <translation>周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizard.cpp" line="108" />
        <source>The drive returned no frequency response.</source>
        <translation>サーボアンプから周波数応答が返されませんでした。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/FrfWizard.cpp" line="121" />
        <source>Adaptive multisine: %n pass(es), %1 s of motion (budget %2 s); %3 of %4 lines valid (%5 %).</source>
        <translation>
            <numerusform>適応マルチサイン: %n パス、動作時間 %1 s (予算 %2 s)。%4 本中 %3 本の周波数線が有効 (%5 %)。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizard.cpp" line="134" />
        <source>Left invalid: %1 by noise (the budget was spent), %2 held by the voltage limit, %3 by the torque limit, %4 non-linear (the passes disagree).</source>
        <translation>無効のまま: ノイズ (予算を使い切った) %1 本、電圧制限 %2 本、トルク制限 %3 本、非線形 (パス間で不一致) %4 本。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/FrfWizard.cpp" line="155" />
        <source>Finish stores: the settings (axis %1, %2, %3–%4 Hz, %5 points, %6 % of rated torque), the measured frequency response (%7 points) and the %n resonance(s) found.</source>
        <translation>
            <numerusform>完了で保存する内容: 設定 (軸 %1、%2、%3–%4 Hz、%5 点、定格トルクの %6 %)、測定した周波数応答 (%7 点)、見つかった %n 個の共振。</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizard.cpp" line="262" />
        <source>Session %1 (%2)</source>
        <translation>セッション %1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/FrfWizard.cpp" line="289" />
        <source>The wizard was closed during the run.</source>
        <translation>実行中にウィザードが閉じられました。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/FrfWizard.cpp" line="152" />
        <source>Finish stores: the settings (axis %1, %2, %3–%4 Hz, peak %5 in the units of %6), the measured frequency response (%7 points) and the %n resonance(s) found.</source>
        <translation>
            <numerusform>完了で保存する内容: 設定 (軸 %1、%2、%3–%4 Hz、%6 の単位でピーク値 %5)、測定した周波数応答 (%7 点)、見つかった %n 個の共振。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>axistune::gui::HistoryView</name>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="297" />
        <source>History</source>
        <translation>履歴</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="304" />
        <source>Session number</source>
        <translation>セッション番号</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="305" />
        <source>Days since the first session</source>
        <translation>最初のセッションからの日数</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="306" />
        <source>Reload</source>
        <translation>再読み込み</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="308" />
        <source>Machine:</source>
        <translation>機械:</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="310" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="312" />
        <source>x axis:</source>
        <translation>横軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="326" />
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="326" />
        <location filename="../app/gui/HistoryView.cpp" line="416" />
        <source>Session</source>
        <translation>セッション</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="326" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="371" />
        <source>(no axis)</source>
        <translation>(軸なし)</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="403" />
        <source>History: %1</source>
        <translation>履歴: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="416" />
        <source>Time since the first session</source>
        <translation>最初のセッションからの時間</translation>
    </message>
    <message>
        <location filename="../app/gui/HistoryView.cpp" line="416" />
        <source>d</source>
        <translation>日</translation>
    </message>
</context>
<context>
    <name>axistune::gui::IdentifyDialog</name>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="78" />
        <source>Identify inertia and friction from motion</source>
        <translation>動作からのイナーシャと摩擦の同定</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="85" />
        <source>Identify</source>
        <translation>同定</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="88" />
        <source>Save result…</source>
        <translation>結果を保存…</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="91" />
        <source>Identification result</source>
        <translation>同定結果</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="92" />
        <location filename="../app/gui/IdentifyDialog.cpp" line="193" />
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="107" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="107" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="107" />
        <source>Std. deviation</source>
        <translation>標準偏差</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="107" />
        <source>Std. dev. [%]</source>
        <translation>標準偏差 [%]</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="107" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="126" />
        <source>Records</source>
        <translation>記録</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="128" />
        <source>Estimation record:</source>
        <translation>推定用の記録:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="128" />
        <location filename="../app/gui/IdentifyDialog.cpp" line="153" />
        <source>Browse…</source>
        <translation>参照…</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="130" />
        <source>Estimation record</source>
        <translation>推定用の記録</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="130" />
        <location filename="../app/gui/IdentifyDialog.cpp" line="155" />
        <source>Capture CSV (*.csv);;All files (*)</source>
        <translation>計測データ CSV (*.csv);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="139" />
        <source>m (linear axis)</source>
        <translation>m (直線軸)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="140" />
        <source>rad (rotary axis)</source>
        <translation>rad (回転軸)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="142" />
        <source>N (linear) or N·m (rotary) per unit of the force column, e.g. the drive gain in N/V</source>
        <translation>力の列の 1 単位あたりの N (直線軸) または N·m (回転軸)。例: ドライブのゲイン N/V</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="143" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="145" />
        <source>Zero-phase low-pass on the position before differentiating; the decimation follows from it</source>
        <translation>微分の前に位置へかけるゼロ位相ローパスフィルタ。間引き率はこれから決まります</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="146" />
        <source>Also per-direction friction</source>
        <translation>方向別の摩擦も同定</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="147" />
        <source>Position column:</source>
        <translation>位置の列:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="148" />
        <source>Position unit:</source>
        <translation>位置の単位:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="149" />
        <source>Force column:</source>
        <translation>力の列:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="150" />
        <source>Force scale:</source>
        <translation>力の換算係数:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="151" />
        <source>Low-pass cutoff:</source>
        <translation>ローパスのカットオフ:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="153" />
        <source>Validation record (optional):</source>
        <translation>検証用の記録 (任意):</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="155" />
        <source>Validation record</source>
        <translation>検証用の記録</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="163" />
        <source>A column added to the controller output, e.g. force pulses (empty: none)</source>
        <translation>制御器の出力に加える列。例: 力のパルス (空欄: なし)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="164" />
        <source>Reference column:</source>
        <translation>指令位置の列:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="165" />
        <source>Added to the command:</source>
        <translation>指令に加える列:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="171" />
        <source>Controller of the validation record</source>
        <translation>検証用の記録の制御器</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="173" />
        <source>u = sat(kv·(kp·(r − q) − v)), v from a two-tap average of q and a backward difference; force = scale·u</source>
        <translation>u = sat(kv·(kp·(r − q) − v))。v は q の 2 タップ平均の後退差分。力 = 換算係数·u</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="178" />
        <source> 1/s</source>
        <translation> 1/s</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="183" />
        <source> samples</source>
        <translation> サンプル</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="185" />
        <source>0: the force scale of the estimation record</source>
        <translation>0: 推定用の記録の力の換算係数</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="186" />
        <source>Position gain kp:</source>
        <translation>位置ゲイン kp:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="187" />
        <source>Velocity gain kv:</source>
        <translation>速度ゲイン kv:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="188" />
        <source>Saturation ±:</source>
        <translation>飽和 ±:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="189" />
        <source>Delay:</source>
        <translation>遅れ:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="190" />
        <source>Force per command unit:</source>
        <translation>指令 1 単位あたりの力:</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="191" />
        <source>Load controller file…</source>
        <translation>制御器ファイルを読み込む…</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="193" />
        <source>Controller</source>
        <translation>制御器</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="219" />
        <source>%1: %2 samples, %3 columns</source>
        <translation>%1: %2 サンプル、%3 列</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="271" />
        <source>Load the estimation record first.</source>
        <translation>先に推定用の記録を読み込んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="289" />
        <source>Not identified: %1</source>
        <translation>同定できません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="307" />
        <source>Validation not possible: %1</source>
        <translation>検証できません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="328" />
        <source>Inertia</source>
        <translation>イナーシャ</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="329" />
        <source>Viscous friction</source>
        <translation>粘性摩擦</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="330" />
        <source>Coulomb friction</source>
        <translation>クーロン摩擦</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="331" />
        <source>Offset</source>
        <translation>オフセット</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="333" />
        <source>Viscous friction, forward</source>
        <translation>粘性摩擦 (正方向)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="334" />
        <source>Viscous friction, backward</source>
        <translation>粘性摩擦 (負方向)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="335" />
        <source>Coulomb friction, forward</source>
        <translation>クーロン摩擦 (正方向)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="336" />
        <source>Coulomb friction, backward</source>
        <translation>クーロン摩擦 (負方向)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="340" />
        <source>Identified from %1 equations (decimation %2, %3 Hz): condition number %4 (scaled %5), residual %6 %7 rms (%8 % of the force)</source>
        <translation>%1 本の式から同定 (間引き %2、%3 Hz): 条件数 %4 (正規化 %5)、残差 %6 %7 rms (力の %8 %)</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="364" />
        <source>measured position</source>
        <translation>測定位置</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="365" />
        <source>simulated position</source>
        <translation>シミュレーション位置</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="366" />
        <source>position error</source>
        <translation>位置誤差</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="370" />
        <source>Validation on %1: position error %2 %3 rms, %4 %3 max, %5 % of the motion's rms; benchmark errors: position %6 %, force %7 %</source>
        <translation>%1 での検証: 位置誤差 %2 %3 rms、最大 %4 %3、動作の rms の %5 %。ベンチマークの誤差: 位置 %6 %、力 %7 %</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="379" />
        <source>Nothing to save: run the identification first.</source>
        <translation>保存するものがありません。先に同定を実行してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/IdentifyDialog.cpp" line="389" />
        <source>%1 cannot be written: %2</source>
        <translation>%1 に書き込めません: %2</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LogPanel</name>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="37" />
        <source>Log</source>
        <translation>ログ</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="38" />
        <source>Parameter journal</source>
        <translation>パラメータ変更履歴</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="39" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="39" />
        <source>Axis</source>
        <translation>軸</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="39" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="39" />
        <source>Old (SI)</source>
        <translation>旧値 (SI)</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="39" />
        <source>New (SI)</source>
        <translation>新値 (SI)</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="39" />
        <source>Session</source>
        <translation>セッション</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="63" />
        <source>Reading the journal of %1 failed: %2</source>
        <translation>%1 の変更履歴の読み出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/LogPanel.cpp" line="75" />
        <source>not recorded</source>
        <translation>記録なし</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionCirclePage</name>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="190" />
        <source>Circle tests</source>
        <translation>円弧補間テスト</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="191" />
        <source>Both plane axes move on circles at the table positions chosen. Abort stops the running circle at once; the drive restores the parameters of both axes.</source>
        <translation>平面の 2 軸が、選んだテーブル位置で円弧を描いて動きます。中止すると実行中の円弧をただちに停止し、サーボアンプが両軸のパラメータを元に戻します。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="201" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="204" />
        <source>Run again</source>
        <translation>再実行</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="224" />
        <source>Completed: %1 circles.</source>
        <translation>完了: 円弧 %1 回。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="225" />
        <source>Aborted: %1</source>
        <translation>中止: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="225" />
        <source>Failed: %1</source>
        <translation>失敗: %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionDiagnosticsPage</name>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="257" />
        <source>Ball-bar diagnostics</source>
        <translation>ボールバー診断</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="258" />
        <source>Measured traces over the nominal circle (deviation magnified), reversal markers, and every finding with the rule that decided it.</source>
        <translation>基準円上の測定軌跡 (偏差を拡大)、反転位置の印、各診断結果とその判定ルール。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="264" />
        <source>Finding</source>
        <translation>診断結果</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="264" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="264" />
        <source>Rule</source>
        <translation>ルール</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="300" />
        <source>Analysing %1 traces…</source>
        <translation>%1 本の軌跡を解析中…</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="346" />
        <source>%1 = %2 mm</source>
        <translation>%1 = %2 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="348" />
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="349" />
        <source>X rev.</source>
        <translation>X 反転</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="350" />
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="351" />
        <source>Y rev.</source>
        <translation>Y 反転</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="358" />
        <source>not computed</source>
        <translation>未計算</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="363" />
        <source>%1 traces, %2 reversal events of axis %3.</source>
        <translation>軌跡 %1 本、軸 %3 の反転 %2 回。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="367" />
        <source>Analysis failed: %1</source>
        <translation>解析に失敗しました: %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionFitPage</name>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="378" />
        <source>A/B fit and predicted compensation</source>
        <translation>A/B の同定と補正の予測</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="379" />
        <source>Δx = (A + B·x)·ΔT (spec eq. 4.12): each reversal gives a point Δx/ΔT at its spring length x; the line is A + B·x. The torque-synchronous compensation (A + B·x)·T_m is predicted on the measured trace, next to the conventional step of the mean lost motion.</source>
        <translation>Δx = (A + B·x)·ΔT (仕様 式 4.12): 各反転がばね長 x での点 Δx/ΔT を与え、直線が A + B·x です。トルク同期補正 (A + B·x)·T_m を測定軌跡上で予測し、平均ロストモーションの従来のステップ補正と並べて示します。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="390" />
        <source>Spring length x</source>
        <translation>ばね長 x</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="390" />
        <source>Δx/ΔT</source>
        <translation>Δx/ΔT</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="396" />
        <source>Trace</source>
        <translation>軌跡</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="396" />
        <source>Circularity measured / proposed / conventional</source>
        <translation>真円度 測定 / 提案法 / 従来法</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="397" />
        <source>Cut-in measured / proposed / conventional</source>
        <translation>食い込み 測定 / 提案法 / 従来法</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="419" />
        <source>reversals</source>
        <translation>反転</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="421" />
        <source>A + B·x</source>
        <translation>A + B·x</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="425" />
        <source>A = %1 µm/(N·m), B = %2 µm/(N·m·m) (%3, %4 points, residual rms %5 µm).</source>
        <translation>A = %1 µm/(N·m)、B = %2 µm/(N·m·m) (%3、%4 点、残差 rms %5 µm)。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="432" />
        <source>Standard errors: A ±%1, B ±%2.</source>
        <translation>標準誤差: A ±%1、B ±%2。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="434" />
        <source>Warning: %1</source>
        <translation>警告: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="435" />
        <source>Rule: least squares on the regressors [ΔT, x·ΔT] over all reversals (two points: the general two-point form); conventional step for comparison x_bl = %1 µm (mean measured lost motion).</source>
        <translation>ルール: すべての反転について回帰変数 [ΔT, x·ΔT] の最小二乗法 (2 点のときは一般的な 2 点式); 比較用の従来のステップ補正 x_bl = %1 µm (測定したロストモーションの平均)。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="444" />
        <source>measured</source>
        <translation>測定</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="445" />
        <source>predicted, proposed</source>
        <translation>予測、提案法</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="446" />
        <source>predicted, conventional</source>
        <translation>予測、従来法</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="448" />
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="449" />
        <source>%1 rev.</source>
        <translation>%1 反転</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="455" />
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="457" />
        <source>%1 / %2 / %3 µm</source>
        <translation>%1 / %2 / %3 µm</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionSavePage</name>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="58" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="59" />
        <source>The session holds the traces, the diagnostics, A and B with their points, the proposal, what was applied with its journal, and the verification.</source>
        <translation>セッションには、軌跡、診断、A と B およびその点、提案、適用した内容とその履歴、検証が保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="78" />
        <source>Axis %1: A = %2 µm/(N·m), B = %3 µm/(N·m·m), x₀ = %4 mm.</source>
        <translation>軸 %1: A = %2 µm/(N·m)、B = %3 µm/(N·m·m)、x₀ = %4 mm。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="84" />
        <source>Not connected: applying the compensation and verifying it with a new circle need a connection to the machine.</source>
        <translation>未接続: 補正の適用と新しい円弧での検証には機械との接続が必要です。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="87" />
        <source>Not applied: the proposal is kept in the session.</source>
        <translation>未適用: 提案はセッションに保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="89" />
        <source>Applied; reversal step %1 µm before, %2 µm after.</source>
        <translation>適用しました。反転時の段差 前 %1 µm、後 %2 µm。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="92" />
        <source>Saved as session %1.</source>
        <translation>セッション %1 として保存しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="93" />
        <source>The session was not saved (no store open).</source>
        <translation>セッションは保存されませんでした (データベースが開かれていません)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionSourcePage</name>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="57" />
        <source>Lost motion: ball-bar traces</source>
        <translation>ロストモーション: ボールバーの軌跡</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="58" />
        <source>Import ball-bar files or run circle tests at two or more table positions. The spring length x of each reversal is x₀ + s·(circle centre ± R) along the identified axis.</source>
        <translation>ボールバーのファイルを読み込むか、2 か所以上のテーブル位置で円弧補間テストを実行してください。各反転のばね長 x は、同定する軸方向の x₀ + s·(円の中心 ± R) です。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="62" />
        <source>Import ball-bar files (CSV)</source>
        <translation>ボールバーのファイルを読み込む (CSV)</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="63" />
        <source>Run circle tests on the machine</source>
        <translation>機械で円弧補間テストを実行</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="80" />
        <source>Add files…</source>
        <translation>ファイルを追加…</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="81" />
        <source>Clear</source>
        <translation>クリア</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="106" />
        <source>Circle radius R:</source>
        <translation>円の半径 R:</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="107" />
        <source>Feed:</source>
        <translation>送り速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="108" />
        <source>Circle centres along the identified axis [mm]:</source>
        <translation>同定する軸方向の円の中心 [mm]:</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="114" />
        <source>Model of the axis</source>
        <translation>軸のモデル</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="118" />
        <source>First plane axis (X)</source>
        <translation>平面の第 1 軸 (X)</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="118" />
        <source>Second plane axis (Y)</source>
        <translation>平面の第 2 軸 (Y)</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="132" />
        <source>Half-width of the zone around each reversal left out of the step fit: the friction spike must not count as lost motion (±8° at 1000 mm/min, R 50 mm).</source>
        <translation>段差の同定から除外する各反転周りの範囲の半幅: 摩擦による突起をロストモーションに数えないため (1000 mm/min、R 50 mm で ±8°)。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="134" />
        <source>Axis to identify:</source>
        <translation>同定する軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="135" />
        <source>Screw length offset x₀ (coupling to load point at table 0):</source>
        <translation>ねじ長さのオフセット x₀ (テーブル位置 0 でのカップリングから負荷点まで):</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="136" />
        <source>Sign s (spring length grows with the coordinate: +1):</source>
        <translation>符号 s (座標とともにばね長が増える: +1):</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="137" />
        <source>Reversal zone ±:</source>
        <translation>反転範囲 ±:</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="143" />
        <source>Ball-bar files</source>
        <translation>ボールバーのファイル</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="143" />
        <source>Ball-bar CSV (*.csv);;All files (*)</source>
        <translation>ボールバー CSV (*.csv);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="168" />
        <source>%1 — R %2 mm, centre (%3, %4) mm, %5 samples</source>
        <translation>%1 — R %2 mm、中心 (%3, %4) mm、%5 サンプル</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardPages.cpp" line="185" />
        <source>Circle tests run on %1 with the drive's current parameters; both plane axes move.</source>
        <translation>円弧補間テストは %1 で現在のサーボアンプのパラメータのまま実行します。平面の 2 軸が動きます。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionVerifyPage</name>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="270" />
        <source>Verify with a new circle</source>
        <translation>新しい円弧で検証</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="271" />
        <source>A circle at the last table position with the compensation applied: measured against the prediction and against the trace before.</source>
        <translation>補正を適用して最後のテーブル位置で円弧を描き、予測および適用前の軌跡と比較します。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="280" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="288" />
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="288" />
        <source>Before</source>
        <translation>適用前</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="288" />
        <source>Predicted</source>
        <translation>予測</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="288" />
        <source>Measured</source>
        <translation>測定値</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="305" />
        <source>Aborted: %1</source>
        <translation>中止: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="305" />
        <source>Failed: %1</source>
        <translation>失敗: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="308" />
        <source>The verification circle failed: %1</source>
        <translation>検証の円弧補間テストが失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="325" />
        <source>The compensation was not applied: nothing to verify.</source>
        <translation>補正は適用されていません: 検証するものはありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="331" />
        <source>Verify with a new ball-bar measurement and compare it in the session review.</source>
        <translation>新しいボールバー測定で検証し、セッションの確認画面で比較してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="365" />
        <source>before</source>
        <translation>適用前</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="366" />
        <source>predicted</source>
        <translation>予測</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="367" />
        <source>measured after</source>
        <translation>適用後の測定</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="369" />
        <source>Reversal step of %1</source>
        <translation>%1 の反転時の段差</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="371" />
        <source>Circularity</source>
        <translation>真円度</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="374" />
        <source>The reversal step fell from %1 to %2. If the result is worse than predicted, restore the previous values on the apply page (Back).</source>
        <translation>反転時の段差は %1 から %2 に減りました。予測より悪い場合は、適用ページ (戻る) で以前の値に戻してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizardRuns.cpp" line="377" />
        <source>The reversal step did not fall (%1 → %2): check x₀ and the sign, or restore the previous values on the apply page (Back).</source>
        <translation>反転時の段差は減りませんでした (%1 → %2): x₀ と符号を確認するか、適用ページ (戻る) で以前の値に戻してください。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::LostMotionWizard</name>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="99" />
        <source>Lost motion</source>
        <translation>ロストモーション</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="104" />
        <source>Circle tests: both axes of the plane move together on circles (radius and centres as set on the first page) at the programmed feed, one circle per table position, and once more for the verification.</source>
        <translation>円弧補間テスト: 平面の 2 軸が一緒に、指定した送り速度で円弧を描きます (半径と中心は最初のページの設定)。テーブル位置ごとに 1 回、検証でもう 1 回。</translation>
    </message>
    <message>
        <location filename="../app/gui/LostMotionWizard.cpp" line="124" />
        <source>the lost-motion compensation</source>
        <translation>ロストモーション補正</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningAdvicePage</name>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="256" />
        <source>Spindle speed advice</source>
        <translation>主軸回転数の提案</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="257" />
        <source>From the chatter frequency heard or measured at the current speed: the stable pocket where the tooth passing frequency divides the chatter frequency by a whole number.</source>
        <translation>現在の回転数で聞こえた、または測定したびびり振動周波数から: 刃通過周波数がびびり振動周波数を整数で割り切る安定ポケット。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="261" />
        <source>e.g. 1450</source>
        <translation>例: 1450</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="262" />
        <source>Estimate from a capture…</source>
        <translation>計測データから推定…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="273" />
        <source>Spindle speed</source>
        <translation>主軸回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="273" />
        <source>min⁻¹</source>
        <translation>min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="273" />
        <source>Limit depth</source>
        <translation>限界切込み深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="273" />
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="275" />
        <source>Chatter frequency [Hz]</source>
        <translation>びびり振動周波数 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="284" />
        <source>entered</source>
        <translation>入力値</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="288" />
        <source>Capture with chatter</source>
        <translation>びびり振動を含む計測データ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="289" />
        <source>Capture CSV (*.csv);;All files (*)</source>
        <translation>計測データ CSV (*.csv);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="324" />
        <source>%1: no signal channel or no sample rate (t_s or fs_Hz)</source>
        <translation>%1: 信号の列またはサンプリング周波数 (t_s または fs_Hz) がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="341" />
        <source>%1: no chatter frequency estimated%2</source>
        <translation>%1: びびり振動周波数を推定できませんでした%2</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="350" />
        <source>Estimated %1 Hz from channel %2 of %3 (Kalman AR model, last half of the record).</source>
        <translation>%3 の列 %2 から %1 Hz と推定しました (カルマン AR モデル、記録の後半)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="365" />
        <source>current</source>
        <translation>現在</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="368" />
        <source>Enter the chatter frequency (or estimate it from a capture) for the advice; this step is optional.</source>
        <translation>提案のためにびびり振動周波数を入力してください (または計測データから推定)。この手順は省略できます。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="371" />
        <source>Chatter frequency: '%1' is not a number</source>
        <translation>びびり振動周波数: '%1' は数値ではありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="381" />
        <source>lobe %1: %2 min⁻¹</source>
        <translation>ローブ %1: %2 min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="383" />
        <source>Rule: the tooth passing frequency f_TPE = N_t·n/60 = %1 × %2 / 60 = %3 Hz; the chatter frequency is %4 × f_TPE. Rounded, lobe number ρ = %5. The stable pocket puts a whole number of chatter waves in one tooth period: n = 60·f_chat/(ρ·N_t) = 60 × %6 / (%5 × %1) = %7 min⁻¹.%8</source>
        <translation>ルール: 刃通過周波数 f_TPE = N_t·n/60 = %1 × %2 / 60 = %3 Hz; びびり振動周波数は %4 × f_TPE。丸めてローブ番号 ρ = %5。安定ポケットでは 1 刃周期に整数個のびびり波が入ります: n = 60·f_chat/(ρ·N_t) = 60 × %6 / (%5 × %1) = %7 min⁻¹。%8</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="390" />
        <source> Neighbouring pockets: %1.</source>
        <translation> 隣の安定ポケット: %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="391" />
        <source>advised %1 min⁻¹</source>
        <translation>推奨 %1 min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="394" />
        <source>The lobe diagram gives %1 mm there.</source>
        <translation>安定限界線図ではそこで %1 mm です。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningAnalysisPage</name>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="205" />
        <source>Analysis of a cut</source>
        <translation>切削の解析</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="206" />
        <source>Load a captured cut or simulate this cut on the vmc X axis: the cutting force estimated by the observer and the chatter intervals found by the correlation detector.</source>
        <translation>計測した切削を読み込むか、vmc の X 軸でこの切削をシミュレーションします: 切削力オブザーバで推定した切削力と、相関検出で見つかったびびり振動の区間。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="208" />
        <source>Load capture CSV…</source>
        <translation>計測データ CSV を読み込む…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="210" />
        <source>Simulate this cut (vmc X)</source>
        <translation>この切削をシミュレーション (vmc X)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="217" />
        <source>empty: the axis parameters of the simulated machine named in the capture</source>
        <translation>空欄: 計測データに記載のシミュレーション機の軸パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="218" />
        <source>stage.json…</source>
        <translation>stage.json…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="226" />
        <source>Start [s]</source>
        <translation>開始 [s]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="226" />
        <source>End [s]</source>
        <translation>終了 [s]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="226" />
        <source>Frequency [Hz]</source>
        <translation>周波数 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="226" />
        <source>Score</source>
        <translation>スコア</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="237" />
        <source>duration [s]</source>
        <translation>時間 [s]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="241" />
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="266" />
        <source>Stage</source>
        <translation>ステージ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="259" />
        <source>Captured cut</source>
        <translation>計測した切削</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="259" />
        <source>Capture CSV (*.csv);;All files (*)</source>
        <translation>計測データ CSV (*.csv);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="266" />
        <source>Stage JSON (*.json);;All files (*)</source>
        <translation>ステージ JSON (*.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="289" />
        <source>Working…</source>
        <translation>処理中…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="316" />
        <source>The tool or cut data are not valid.</source>
        <translation>工具または切削のデータが正しくありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="317" />
        <source>duration: a number of seconds in (0.3, 10]</source>
        <translation>時間: (0.3, 10] の秒数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="321" />
        <source>simulated cut on vmc X, %1 min⁻¹, %2 mm</source>
        <translation>vmc X でのシミュレーション切削、%1 min⁻¹、%2 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="343" />
        <source>Not analysed: %1</source>
        <translation>未解析: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="349" />
        <source>cutting force (in the capture)</source>
        <translation>切削力 (計測データ内)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="350" />
        <source>cutting force (observer)</source>
        <translation>切削力 (切削力オブザーバ)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="354" />
        <source>tool vibration x</source>
        <translation>工具振動 x</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="372" />
        <source>chatter detected</source>
        <translation>びびり振動検出</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="372" />
        <source>flag</source>
        <translation>フラグ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="376" />
        <source>%1 (stage: %2). </source>
        <translation>%1 (ステージ: %2)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="378" />
        <source>No chatter detection: the stage has no coupling stiffness.</source>
        <translation>びびり振動検出なし: ステージに結合剛性がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="380" />
        <source>No chatter detected (vibration mode %1 Hz, %2 % of the valid windows flagged).</source>
        <translation>びびり振動は検出されませんでした (振動モード %1 Hz、有効な窓の %2 % でフラグ)。</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/MachiningWizardAnalysis.cpp" line="383" />
        <source>CHATTER: %n interval(s) detected (vibration mode %1 Hz).</source>
        <translation>
            <numerusform>びびり振動: %n 区間を検出 (振動モード %1 Hz)。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningAvoidancePage</name>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="74" />
        <source>Chatter avoidance in the loop</source>
        <translation>ループ内のびびり振動回避</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="75" />
        <source>Runs this cut on the simulated vmc X axis while an avoidance method changes the spindle speed: the adaptive stable-pocket rule, the multi-resonance search or extremum seeking.</source>
        <translation>回避手法が主軸回転数を変えながら、シミュレーションした vmc の X 軸でこの切削を行います: 適応的な安定ポケット則、複数共振の探索、または極値探索制御。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="79" />
        <source>none (constant speed)</source>
        <translation>なし (一定回転数)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="80" />
        <source>adaptive (stable pocket)</source>
        <translation>適応 (安定ポケット)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="81" />
        <source>multimode (J_chat search)</source>
        <translation>複数モード (J_chat 探索)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="82" />
        <source>ESC (extremum seeking)</source>
        <translation>ESC (極値探索制御)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="86" />
        <source>accelerometer on the spindle</source>
        <translation>主軸の加速度センサ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="87" />
        <source>feed-stage disturbance observer</source>
        <translation>送りステージの外乱オブザーバ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="99" />
        <source>Assumed curvature f'' of the cost near its minimum. The cost scales with the feed squared: the seed's 1e5 is for its 0.5 mm/s table feed; this page cuts with f_z 0.1 mm</source>
        <translation>最小点付近の評価関数の仮定曲率 f''。評価関数は送りの二乗に比例します。シードの 1e5 はテーブル送り 0.5 mm/s に対する値で、このページは f_z 0.1 mm で切削します</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="105" />
        <source>table</source>
        <translation>表の値</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="106" />
        <source>Trigger threshold on the squared filtered signal ((m/s²)² or N²); empty: the table value (Table 3/4/5). Table 4's 1e4 N² was set for a 3.5 mm cut</source>
        <translation>フィルタ後の信号の二乗に対する起動しきい値（(m/s²)² または N²）。空欄: 表の値（表 3/4/5）。表 4 の 1e4 N² は切込み 3.5 mm の切削に対して設定された値です</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="152" />
        <source>trigger σ_th</source>
        <translation>起動しきい値 σ_th</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="263" />
        <source>trigger σ_th: a number &gt; 0, or empty for the table value</source>
        <translation>起動しきい値 σ_th: 0 より大きい数値、または表の値を使う場合は空欄</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="387" />
        <source>Never triggered: the filtered signal squared stayed below σ_th (set a lower trigger σ_th for this cut).</source>
        <translation>起動しませんでした: フィルタ後の信号の二乗が σ_th 未満のままでした（この切削にはより低い起動しきい値 σ_th を設定してください）。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="110" />
        <source>Run cut</source>
        <translation>切削を実行</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="112" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="122" />
        <source>Frequency</source>
        <translation>周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="122" />
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="355" />
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="122" />
        <source>PSD of the acceleration</source>
        <translation>加速度の PSD</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="122" />
        <source>(m/s²)²/Hz</source>
        <translation>(m/s²)²/Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="125" />
        <source>Spindle speed</source>
        <translation>主軸回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="125" />
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="351" />
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="352" />
        <source>min⁻¹</source>
        <translation>min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="125" />
        <source>Limit depth</source>
        <translation>限界切込み深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="125" />
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="130" />
        <source>Moves the operating point on the lobes through the cut</source>
        <translation>切削中の動作点を安定限界線図上で動かします</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="136" />
        <source>Method</source>
        <translation>手法</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="138" />
        <source>Sensor</source>
        <translation>センサ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="140" />
        <source>duration [s]</source>
        <translation>時間 [s]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="142" />
        <source>ESC from [s]</source>
        <translation>ESC 開始 [s]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="144" />
        <source>ESC bounds [min⁻¹]</source>
        <translation>ESC 範囲 [min⁻¹]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="150" />
        <source>ESC f''</source>
        <translation>ESC f''</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="227" />
        <source>The tool or cut data are not valid.</source>
        <translation>工具または切削のデータが正しくありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="232" />
        <source>duration: a number of seconds in [0.3, 20]</source>
        <translation>時間: 0.3～20 の秒数を入力してください</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="272" />
        <source>ESC: the start time (before the end of the cut), both speed bounds and f'' must be numbers</source>
        <translation>ESC: 開始時刻 (切削終了前)、回転数の上下限、f'' はいずれも数値で入力してください</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="288" />
        <source>Running…</source>
        <translation>実行中…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="342" />
        <source>Aborted: %1</source>
        <translation>中止: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="342" />
        <source>Error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="349" />
        <source>tool acceleration y</source>
        <translation>工具加速度 y</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="351" />
        <source>spindle speed</source>
        <translation>主軸回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="352" />
        <source>spindle speed command</source>
        <translation>主軸回転数指令</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="355" />
        <source>estimated chatter frequency</source>
        <translation>推定びびり周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="359" />
        <source>cost (signal squared)</source>
        <translation>評価関数 (信号の二乗)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="359" />
        <source>self-excited power</source>
        <translation>自励振動パワー</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="367" />
        <source>start of the cut</source>
        <translation>切削開始時</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="369" />
        <source>last 0.3 s</source>
        <translation>最後の 0.3 s</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="376" />
        <source>Final spindle speed %1 min⁻¹.</source>
        <translation>最終の主軸回転数 %1 min⁻¹。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="378" />
        <source>Acceleration RMS over the last 0.3 s: %1 m/s² (constant speed %2 m/s², %3 % lower).</source>
        <translation>最後の 0.3 s の加速度 RMS: %1 m/s² (一定回転数では %2 m/s²、%3 % 低減)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="390" />
        <source>ESC: dither %1 Hz, h_c %2 Hz, k_c %3 1/s; %4 samples held at a bound.</source>
        <translation>ESC: 摂動 %1 Hz、h_c %2 Hz、k_c %3 1/s。上下限で保持したサンプル数 %4。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="408" />
        <source>limit depth</source>
        <translation>限界切込み深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="416" />
        <source>operating point path</source>
        <translation>動作点の軌跡</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="419" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="422" />
        <source>now</source>
        <translation>現在</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/MachiningAvoidancePage.cpp" line="384" />
        <source>Triggered at %1 s; %n adaptation step(s).</source>
        <translation>
            <numerusform>%1 s で起動しました。適応ステップ %n 回。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningCutPage</name>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="322" />
        <location filename="../app/gui/MachiningWizard.cpp" line="363" />
        <source>Cutting data</source>
        <translation>切削条件</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="323" />
        <source>The cutter, the material's specific cutting forces, the engagement and the current operating point.</source>
        <translation>工具、材料の比切削抵抗、切込み、現在の加工条件。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="342" />
        <source>Down milling (climb)</source>
        <translation>ダウンカット</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="343" />
        <source>Up milling (conventional)</source>
        <translation>アップカット</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="354" />
        <source>Time steps per tooth period of the semi-discretization: 40 gives the limit depth within ~8 %, 80 within ~3 %, 160 within ~1 % (docs/machining.md).</source>
        <translation>半離散化の 1 刃周期あたりの時間ステップ数: 40 で限界切込み深さは約 8 % 以内、80 で約 3 % 以内、160 で約 1 % 以内 (docs/machining.md)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="360" />
        <source>Load cut.json…</source>
        <translation>cut.json を読み込む…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="363" />
        <source>Cut JSON (*.json);;All files (*)</source>
        <translation>切削 JSON (*.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="369" />
        <source>Teeth</source>
        <translation>刃数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="370" />
        <source>Tangential specific cutting force K_t [GPa = kN/mm²]</source>
        <translation>接線方向の比切削抵抗 K_t [GPa = kN/mm²]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="371" />
        <source>Radial specific cutting force K_r [GPa = kN/mm²]</source>
        <translation>半径方向の比切削抵抗 K_r [GPa = kN/mm²]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="372" />
        <source>Radial immersion a_e/D (0–1]</source>
        <translation>半径方向切込み比 a_e/D (0–1]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="373" />
        <source>Milling</source>
        <translation>切削方向</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="374" />
        <source>Spindle speed [min⁻¹]</source>
        <translation>主軸回転数 [min⁻¹]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="375" />
        <source>Axial depth of cut [mm]</source>
        <translation>軸方向切込み深さ [mm]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="378" />
        <source>to</source>
        <translation>〜</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="380" />
        <source>step</source>
        <translation>刻み</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="382" />
        <source>Lobe diagram speeds [min⁻¹]</source>
        <translation>安定限界線図の回転数 [min⁻¹]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="383" />
        <source>Steps per tooth period</source>
        <translation>1 刃周期あたりのステップ数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="418" />
        <source>K_t</source>
        <translation>K_t</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="419" />
        <source>K_r</source>
        <translation>K_r</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="420" />
        <source>radial immersion</source>
        <translation>半径方向切込み比</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="421" />
        <source>spindle speed</source>
        <translation>主軸回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="422" />
        <source>axial depth</source>
        <translation>軸方向切込み深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="423" />
        <source>lowest speed</source>
        <translation>最低回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="424" />
        <source>highest speed</source>
        <translation>最高回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="425" />
        <source>speed step</source>
        <translation>回転数の刻み</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="431" />
        <source>%1: '%2' is not a number</source>
        <translation>%1: '%2' は数値ではありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="441" />
        <source>spindle speed must be &gt; 0 min⁻¹</source>
        <translation>主軸回転数は 0 min⁻¹ より大きくしてください</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="443" />
        <source>axial depth must be ≥ 0 mm</source>
        <translation>軸方向切込み深さは 0 mm 以上にしてください</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="446" />
        <source>lobe diagram speeds: </source>
        <translation>安定限界線図の回転数: </translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="450" />
        <source>lobe diagram speeds: %1 speeds; at most 2000 (a larger step)</source>
        <translation>安定限界線図の回転数: %1 点; 最大 2000 点です (刻みを大きくしてください)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningLobesPage</name>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="63" />
        <source>Stability lobes</source>
        <translation>安定限界線図</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="64" />
        <source>Limit axial depth against spindle speed by semi-discretization: below the curve the cut is stable, above it chatters.</source>
        <translation>半離散化法による主軸回転数に対する限界軸方向切込み深さ: 曲線より下では安定、上ではびびり振動が発生します。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="68" />
        <source>Spindle speed</source>
        <translation>主軸回転数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="68" />
        <source>min⁻¹</source>
        <translation>min⁻¹</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="68" />
        <source>Limit depth</source>
        <translation>限界切込み深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="68" />
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="71" />
        <source>Cancel</source>
        <translation>キャンセル</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="73" />
        <source>Compute again</source>
        <translation>再計算</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="131" />
        <source>The tool or cut data are not valid.</source>
        <translation>工具または切削のデータが正しくありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="142" />
        <source>Computing %1 spindle speeds (%2 steps per tooth period)…</source>
        <translation>%1 点の主軸回転数を計算中 (1 刃周期あたり %2 ステップ)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="197" />
        <source>Cancelled: no lobe diagram. Press Compute again.</source>
        <translation>キャンセルしました: 安定限界線図はありません。再計算を押してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="203" />
        <source>The lobes could not be computed: %1</source>
        <translation>安定限界線図を計算できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="216" />
        <source>stable up to the search limit %1 mm</source>
        <translation>探索上限 %1 mm まで安定</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="217" />
        <source>limit %1 mm</source>
        <translation>限界 %1 mm</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="218" />
        <source>current: stable</source>
        <translation>現在: 安定</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="218" />
        <source>current: unstable</source>
        <translation>現在: 不安定</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="226" />
        <source>Current point %1 min⁻¹, %2 mm: %3 (%4 at this speed).</source>
        <translation>現在の加工点 %1 min⁻¹、%2 mm: %3 (この回転数で %4)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="228" />
        <source>STABLE</source>
        <translation>安定</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizardPages.cpp" line="228" />
        <source>UNSTABLE (chatter expected)</source>
        <translation>不安定 (びびり振動の発生が予想されます)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningSavePage</name>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="470" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="471" />
        <source>The session (kind "machining") stores the tool and cut data, the lobes, the advice, the chatter intervals and the analysed cut.</source>
        <translation>セッション (種類 "machining") には、工具と切削のデータ、安定限界線図、提案、びびり振動の区間、解析した切削が保存されます。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningTapPage</name>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="64" />
        <source>Tap test</source>
        <translation>打撃試験</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="65" />
        <source>Impact-hammer records at the tool tip: the receptance (m/N) from hammer force and response, averaged over the hits, used as the tool's FRF.</source>
        <translation>工具先端のインパクトハンマー記録: ハンマーの力と応答からレセプタンス (m/N) を求め、打撃ごとに平均して工具の周波数応答として使います。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="70" />
        <source>Add record…</source>
        <translation>記録を追加…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="72" />
        <source>Remove</source>
        <translation>削除</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="79" />
        <source>acceleration [m/s²]</source>
        <translation>加速度 [m/s²]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="80" />
        <source>velocity [m/s]</source>
        <translation>速度 [m/s]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="81" />
        <source>displacement [m]</source>
        <translation>変位 [m]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="84" />
        <source>10 % of the largest force</source>
        <translation>最大力の 10 %</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="87" />
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="90" />
        <source>refuse the records</source>
        <translation>記録を受け付けない</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="91" />
        <source>drop that hit</source>
        <translation>その打撃を除く</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="96" />
        <source>Force column [N]</source>
        <translation>力の列 [N]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="97" />
        <source>Response column</source>
        <translation>応答の列</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="98" />
        <source>Response measures</source>
        <translation>応答の種類</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="99" />
        <source>Trigger level [N]</source>
        <translation>トリガレベル [N]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="100" />
        <source>Exponential window τ [ms]</source>
        <translation>指数窓 τ [ms]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="101" />
        <source>Double hit</source>
        <translation>二度打ち</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="102" />
        <source>Modes to fit per direction</source>
        <translation>方向ごとに同定するモード数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="103" />
        <source>Compute</source>
        <translation>計算</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="105" />
        <source>Save FRF…</source>
        <translation>周波数応答を保存…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="106" />
        <source>Use as x FRF</source>
        <translation>x の周波数応答に使う</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="108" />
        <source>Use as y FRF</source>
        <translation>y の周波数応答に使う</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="110" />
        <source>Use for x and y</source>
        <translation>x と y に使う</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="148" />
        <source>Impact records</source>
        <translation>打撃記録</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="148" />
        <source>Records (*.csv *.txt *.log *.unv *.uff);;All files (*)</source>
        <translation>記録 (*.csv *.txt *.log *.unv *.uff);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="155" />
        <source>Save receptance</source>
        <translation>レセプタンスを保存</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="155" />
        <source>FRF CSV (*.csv)</source>
        <translation>周波数応答 CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="212" />
        <source>Add at least one impact record.</source>
        <translation>打撃記録を一つ以上追加してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="227" />
        <source>%1: no column '%2'</source>
        <translation>%1: 列 '%2' がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="231" />
        <source>%1: sampled at %2 Hz, the first record at %3 Hz</source>
        <translation>%1: サンプリング %2 Hz、最初の記録は %3 Hz です</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="248" />
        <source>'%1' is not a positive number</source>
        <translation>'%1' は正の数ではありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="260" />
        <source>receptance</source>
        <translation>レセプタンス</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="272" />
        <source>%1 hit(s) averaged, %2 dropped; block %3 s; valid to %4 Hz (force spectrum within 40 dB).</source>
        <translation>%1 回の打撃を平均、%2 回を除外; ブロック長 %3 s; %4 Hz まで有効 (力のスペクトルが 40 dB 以内)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="277" />
        <source>Largest receptance %1 µm/N at %2 Hz.</source>
        <translation>最大レセプタンス %1 µm/N (%2 Hz)。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="281" />
        <source>One hit: no coherence. Average several hits to see how repeatable the measurement is.</source>
        <translation>打撃 1 回: コヒーレンスはありません。測定の再現性を見るには複数回打撃して平均してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="291" />
        <source>Compute the receptance first.</source>
        <translation>先にレセプタンスを計算してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningTapPage.cpp" line="314" />
        <source>Now the other direction's tap test (or use this one for both).</source>
        <translation>次にもう一方の方向の打撃試験を行ってください (またはこの結果を両方に使います)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningToolPage</name>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="70" />
        <source>Tool</source>
        <translation>工具</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="71" />
        <source>Modal parameters of the tool tip per direction (x = feed direction). Modes of one direction add their compliances.</source>
        <translation>方向ごとの工具先端のモードパラメータ (x = 送り方向)。同じ方向のモードはコンプライアンスが加算されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="76" />
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="76" />
        <source>Mass [kg]</source>
        <translation>質量 [kg]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="76" />
        <source>Damping [N·s/m]</source>
        <translation>減衰 [N·s/m]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="76" />
        <source>Stiffness [N/m]</source>
        <translation>剛性 [N/m]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="79" />
        <source>Load tool.json…</source>
        <translation>tool.json を読み込む…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="81" />
        <source>Add x mode</source>
        <translation>x モードを追加</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="82" />
        <source>Add y mode</source>
        <translation>y モードを追加</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="83" />
        <source>Remove mode</source>
        <translation>モードを削除</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="92" />
        <source>Fit to tool-tip FRFs…</source>
        <translation>工具先端の周波数応答から同定…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="94" />
        <source>Modes fitted to measured tool-tip receptances (FRF CSV, h in m/N) in x and y</source>
        <translation>x と y で測定した工具先端のレセプタンス (周波数応答 CSV、h は m/N) からモードを同定します</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="139" />
        <location filename="../app/gui/MachiningWizard.cpp" line="142" />
        <source>entered</source>
        <translation>入力値</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="148" />
        <source>Tool data</source>
        <translation>工具データ</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="148" />
        <source>Tool JSON (*.json);;All files (*)</source>
        <translation>工具 JSON (*.json);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="153" />
        <source>Tool-tip FRF in x (feed direction)</source>
        <translation>x 方向 (送り方向) の工具先端の周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="154" />
        <location filename="../app/gui/MachiningWizard.cpp" line="158" />
        <source>FRF CSV (*.csv);;All files (*)</source>
        <translation>周波数応答 CSV (*.csv);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="157" />
        <source>Tool-tip FRF in y</source>
        <translation>y 方向の工具先端の周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="98" />
        <location filename="../app/gui/MachiningWizard.cpp" line="101" />
        <location filename="../app/gui/MachiningWizard.cpp" line="105" />
        <source>auto</source>
        <translation>自動</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="106" />
        <source>Modes fitted per direction; auto = one per resonance peak above 25 % of the largest</source>
        <translation>方向ごとに同定するモード数。自動 = 最大の共振ピークの 25 % 以上の共振ピークごとに 1 モード</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="107" />
        <source>Fit band lower edge; empty = chosen from the resonance peaks</source>
        <translation>同定帯域の下限。空欄 = 共振ピークから自動選択</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="108" />
        <source>Fit band upper edge; empty = chosen from the resonance peaks</source>
        <translation>同定帯域の上限。空欄 = 共振ピークから自動選択</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="113" />
        <source>FRF fit band [Hz]</source>
        <translation>周波数応答の同定帯域 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="115" />
        <source>to</source>
        <translation>〜</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="118" />
        <source>Modes per direction</source>
        <translation>方向ごとのモード数</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="228" />
        <source>fit refused</source>
        <translation>同定を拒否</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="238" />
        <source>FRF fit band: '%1' is not a number</source>
        <translation>周波数応答の同定帯域: '%1' は数値ではありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="251" />
        <source>%1: %2 mode(s), band %3–%4 Hz (%5), weighted residual %6 %</source>
        <translation>%1: %2 モード、帯域 %3〜%4 Hz (%5)、重み付き残差 %6 %</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="255" />
        <source>automatic</source>
        <translation>自動</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="255" />
        <source>given</source>
        <translation>指定</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="261" />
        <source>fitted to %1 and %2</source>
        <translation>%1 と %2 から同定</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="275" />
        <source>row %1, %2: not a number</source>
        <translation>%1 行目、%2: 数値ではありません</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="304" />
        <source>%1: natural frequency %2 Hz, damping ratio %3 %</source>
        <translation>%1: 固有振動数 %2 Hz、減衰比 %3 %</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MachiningWizard</name>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="508" />
        <source>Tap test…</source>
        <translation>打撃試験…</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="510" />
        <source>Measure the tool-tip receptance with an impact hammer</source>
        <translation>インパクトハンマーで工具先端のレセプタンスを測定します</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="490" />
        <source>Machining: stability lobes and chatter</source>
        <translation>加工: 安定限界線図とびびり振動</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="559" />
        <source>Nothing saved: the tool or cut data are not valid.</source>
        <translation>保存していません: 工具または切削のデータが正しくありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="640" />
        <source>Not saved: %1</source>
        <translation>保存されませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MachiningWizard.cpp" line="644" />
        <source>Saved as session %1: inputs, %2 results, %3 capture(s).</source>
        <translation>セッション %1 として保存しました: 入力、結果 %2 件、計測データ %3 件。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::MainWindow</name>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="152" />
        <source>Abort requested</source>
        <translation>中止を要求しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="204" />
        <source>(no wizards)</source>
        <translation>(ウィザードなし)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="223" />
        <source>AxisTune</source>
        <translation>AxisTune</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="224" />
        <source>&amp;Machine</source>
        <translation>機械(&amp;M)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="225" />
        <source>&amp;Connect…</source>
        <translation>接続(&amp;C)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="226" />
        <source>&amp;Disconnect</source>
        <translation>切断(&amp;D)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="227" />
        <source>&amp;Quit</source>
        <translation>終了(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="228" />
        <source>&amp;Wizards</source>
        <translation>ウィザード(&amp;W)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="229" />
        <source>&amp;Sessions</source>
        <translation>セッション(&amp;S)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="230" />
        <source>&amp;Review…</source>
        <translation>確認(&amp;R)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="231" />
        <source>&amp;History…</source>
        <translation>履歴(&amp;H)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="232" />
        <source>Export NC &amp;parameters…</source>
        <translation>NC パラメータの書き出し(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="233" />
        <source>T&amp;ools</source>
        <translation>ツール(&amp;O)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="234" />
        <source>Identify from &amp;motion…</source>
        <translation>動作からの同定(&amp;M)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="235" />
        <source>Se&amp;ttings</source>
        <translation>設定(&amp;T)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="236" />
        <source>&amp;Preferences…</source>
        <translation>環境設定(&amp;P)…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="237" />
        <source>&amp;Help</source>
        <translation>ヘルプ(&amp;H)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="238" />
        <source>&amp;About AxisTune</source>
        <translation>AxisTune について(&amp;A)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="239" />
        <source>Machine / axis</source>
        <translation>機械 / 軸</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="239" />
        <source>State</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="240" />
        <source>Machines</source>
        <translation>機械</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="241" />
        <source>Parameters</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="242" />
        <source>Log and journal</source>
        <translation>ログと変更履歴</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="245" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="246" />
        <source>Stops the running test at once; the drive restores the parameters from before the test</source>
        <translation>実行中のテストを直ちに止めます。サーボアンプはテスト前のパラメータに戻します</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="249" />
        <location filename="../app/gui/MainWindow.cpp" line="365" />
        <source>Test running</source>
        <translation>テスト実行中</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="222" />
        <source>Saving session %p%</source>
        <translation>セッション保存中 %p%</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="249" />
        <location filename="../app/gui/MainWindow.cpp" line="329" />
        <location filename="../app/gui/MainWindow.cpp" line="353" />
        <source>Idle</source>
        <translation>待機中</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="275" />
        <source>Connected: %1 (machine %2)</source>
        <translation>接続中: %1 (機械 %2)</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="277" />
        <source>Connecting to %1 …</source>
        <translation>%1 に接続中…</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="279" />
        <source>CONNECTION LOST: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="282" />
        <source>Connection failed: %1</source>
        <translation>接続に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="299" />
        <source>Connecting to %1</source>
        <translation>%1 に接続中</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="313" />
        <source>Connected to %1: machine %2, axes %3</source>
        <translation>%1 に接続しました: 機械 %2、軸 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="325" />
        <source>Connection lost: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="340" />
        <source>Connection to %1 failed: %2</source>
        <translation>%1 への接続に失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="346" />
        <source>Disconnected</source>
        <translation>切断しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="354" />
        <source>Test on axis %1 completed</source>
        <translation>軸 %1 のテストが完了しました</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="355" />
        <source>Test on axis %1 ended: %2</source>
        <translation>軸 %1 のテストが終了しました: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/MainWindow.cpp" line="419" />
        <source>%n session(s)</source>
        <translation>
            <numerusform>%n セッション</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="421" />
        <source>connected, %1</source>
        <translation>接続中、%1</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="510" />
        <source>Sessions</source>
        <translation>セッション</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="530" />
        <source>About AxisTune</source>
        <translation>AxisTune について</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="531" />
        <source>&lt;b&gt;AxisTune&lt;/b&gt; %1&lt;br&gt;Commissioning and tuning of NC feed axes.&lt;br&gt;GPL-3.0-or-later.</source>
        <translation>&lt;b&gt;AxisTune&lt;/b&gt; %1&lt;br&gt;NC工作機械送り軸の立上げと調整。&lt;br&gt;GPL-3.0-or-later。</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="285" />
        <source>Not connected</source>
        <translation>未接続</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="243" />
        <source>Scope</source>
        <translation>スコープ</translation>
    </message>
    <message>
        <location filename="../app/gui/MainWindow.cpp" line="244" />
        <source>&amp;Scope</source>
        <translation>スコープ(&amp;S)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NcExportDialog</name>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="48" />
        <source>Export NC parameters</source>
        <translation>NC パラメータの書き出し</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="60" />
        <source>Axis</source>
        <translation>軸</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="60" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="60" />
        <source>NC number</source>
        <translation>NC 番号</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="60" />
        <source>NC value</source>
        <translation>NC の値</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="60" />
        <source>AxisTune value</source>
        <translation>AxisTune の値</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="60" />
        <source>Description</source>
        <translation>説明</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="73" />
        <source>Save file…</source>
        <translation>ファイルに保存…</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="75" />
        <source>Close</source>
        <translation>閉じる</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="78" />
        <source>Machine:</source>
        <translation>機械:</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="79" />
        <source>NC family:</source>
        <translation>NC の種類:</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="80" />
        <source>Show axis:</source>
        <translation>表示する軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="82" />
        <source>Parameters without a mapping (written as comments)</source>
        <translation>対応のないパラメータ (コメントとして書き出し)</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="84" />
        <source>File</source>
        <translation>ファイル</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="158" />
        <source>No store is open.</source>
        <translation>データベースが開かれていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="160" />
        <source>The store holds no machine.</source>
        <translation>データベースに機械がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="162" />
        <source>The profile of %1 cannot be loaded: %2</source>
        <translation>%1 のプロファイルを読み込めません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="169" />
        <source>All axes</source>
        <translation>すべての軸</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="187" />
        <source>NC map %1: %2</source>
        <translation>NC 対応表 %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="192" />
        <source>Export to %1 failed: %2</source>
        <translation>%1 への書き出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="227" />
        <source>error: %1</source>
        <translation>エラー: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="244" />
        <source>%1  %2 = %3</source>
        <translation>%1  %2 = %3</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="260" />
        <source>Nothing to export.</source>
        <translation>書き出すものがありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="276" />
        <source>Save NC parameter file</source>
        <translation>NC パラメータファイルの保存</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="277" />
        <source>Text files (*.txt *.nc *.mpf *.mp);;All files (*)</source>
        <translation>テキストファイル (*.txt *.nc *.mpf *.mp);;すべてのファイル (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="284" />
        <source>NC file not saved</source>
        <translation>NC ファイルは保存されませんでした</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="288" />
        <source>Saved %1. Verify every number against the NC's parameter manual before loading it.</source>
        <translation>%1 を保存しました。読み込む前に、すべての番号を NC のパラメータ説明書で確認してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcExportDialog.cpp" line="290" />
        <source>NC parameters of %1 exported for %2 to %3</source>
        <translation>%1 の NC パラメータを %2 用に %3 へ書き出しました</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NcPidPage</name>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="60" />
        <source>Notch for a position PID the NC closes</source>
        <translation>NCが閉じる位置PIDのノッチ</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="61" />
        <source>Position PID the NC closes</source>
        <translation>NCが閉じる位置PID</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="71" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="72" />
        <source> % of maxoutput</source>
        <translation> % (maxoutput比)</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="73" />
        <source>Excitation peak (multisine at the PID output):</source>
        <translation>加振ピーク (PID出力でのマルチサイン):</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="76" />
        <source>from the measured slope</source>
        <translation>測定した傾きから</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="77" />
        <location filename="../app/gui/NcPidPage.cpp" line="457" />
        <source>torque or current</source>
        <translation>トルクまたは電流</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="78" />
        <location filename="../app/gui/NcPidPage.cpp" line="457" />
        <source>velocity</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="79" />
        <source>Drive input (what the PID output commands):</source>
        <translation>サーボアンプ入力 (PID出力が指令するもの):</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="81" />
        <source>Phase margin asked:</source>
        <translation>要求する位相余裕:</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="82" />
        <source> dB</source>
        <translation> dB</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="83" />
        <source>Gain margin asked:</source>
        <translation>要求するゲイン余裕:</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="84" />
        <source>Propose LinuxCNC's biquad notch when it lets the crossover rise</source>
        <translation>交差周波数を上げられるときは LinuxCNC の biquad ノッチを提案する</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="96" />
        <source>The axis is free to move over the whole test, nobody is inside the machine, and the emergency stop is within reach.</source>
        <translation>テスト全体を通じて軸は自由に動くことができ、機械の中には誰もおらず、非常停止ボタンに手が届きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="102" />
        <source>Measure and propose</source>
        <translation>測定して提案</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="105" />
        <source>Insert the notch and verify</source>
        <translation>ノッチを挿入して検証</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="105" />
        <source>Apply and verify</source>
        <translation>適用して検証</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="107" />
        <source>Undo</source>
        <translation>元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="109" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="111" />
        <source>Undo anyway</source>
        <translation>それでも元に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="119" />
        <source>Overwrite what changed in HAL since the apply with what ran before</source>
        <translation>適用後に HAL で変更された値を、以前の値で上書きする</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="134" />
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="134" />
        <source>Running</source>
        <translation>現在値</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="134" />
        <source>Proposed</source>
        <translation>提案値</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="134" />
        <source>Verified</source>
        <translation>検証値</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="134" />
        <source>Rule</source>
        <translation>ルール</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="139" />
        <source>Open loop L [dB]</source>
        <translation>開ループ L [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="192" />
        <source>Axis %1 is a position loop the NC closes with a PID (%2): it has no drive filter slots. Its notch is LinuxCNC's biquad component (a notch with 0.5 ≤ Q ≤ 2), inserted after the PID output. This page measures the open loop with the gains that run, proposes a notch at the plant's strongest resonance when it raises the gain margin, inserts it and verifies it by measuring again; the gains are not changed.</source>
        <translation>軸 %1 は NC が PID で閉じる位置ループです (%2)。サーボアンプのフィルタスロットはありません。そのノッチは LinuxCNC の biquad コンポーネント (0.5 ≤ Q ≤ 2 のノッチ) で、PID 出力の後に挿入します。このページは現在のゲインで開ループを測定し、ゲイン余裕が上がるときは制御対象の最も強い共振にノッチを提案し、挿入して再測定で検証します。ゲインは変更しません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="198" />
        <source>Axis %1 is a position loop the NC closes with a PID (%2): there is no drive velocity loop. This page measures the open loop with the gains that run, proposes P, I, D, FF1 and FF2 (and a biquad notch after the PID output when it lets the crossover rise) for the margins asked, with the rule behind each number, applies them live and verifies them by measuring again. A loop that misses the margins gets back what ran before.</source>
        <translation>軸 %1 は NC が PID で閉じる位置ループです (%2)。サーボアンプの速度ループはありません。このページは現在のゲインで開ループを測定し、要求された余裕に対して P、I、D、FF1、FF2 (交差周波数を上げられるときは PID 出力の後の biquad ノッチも) を各値のルールとともに提案し、運転中に適用して再測定で検証します。余裕を満たさないループは元の設定に戻します。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="285" />
        <source>Measuring the open loop of %1 with the gains that run…</source>
        <translation>現在のゲインで %1 の開ループを測定しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="300" />
        <source>Aborted: the excitation stopped and what AxisTune inserted was removed. %1</source>
        <translation>中止しました: 加振を止め、AxisTune が挿入したものを取り除きました。%1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="301" />
        <source>Measured, but no proposal: %1</source>
        <translation>測定しましたが提案はありません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="301" />
        <source>The measurement failed: %1</source>
        <translation>測定に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="312" />
        <source>Nothing to change: %1</source>
        <translation>変更するものはありません: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="315" />
        <source>Proposed: a notch at %1 Hz, Q %2. Nothing was written yet.</source>
        <translation>提案: %1 Hz、Q %2 のノッチ。まだ何も書き込んでいません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="317" />
        <source>Proposed below with the predicted margins. Nothing was written yet.</source>
        <translation>提案と予測余裕を下に示します。まだ何も書き込んでいません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="320" />
        <source>proposed, not applied</source>
        <translation>提案のみ、未適用</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="329" />
        <source>Inserting the notch and measuring the open loop again…</source>
        <translation>ノッチを挿入し、開ループを再測定しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="330" />
        <source>Writing the gains (read back) and measuring the open loop again…</source>
        <translation>ゲインを書き込み (読み戻し確認)、開ループを再測定しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="341" />
        <source>Not applied: %1. Nothing was left changed.</source>
        <translation>適用しませんでした: %1。変更は残っていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="347" />
        <source>Applied and verified: the measured margins are in the table. Undo puts back what ran before.</source>
        <translation>適用して検証しました: 測定した余裕は表にあります。「元に戻す」で以前の設定に戻ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="349" />
        <source>Not kept: %1</source>
        <translation>保持しませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="352" />
        <source>applied and verified</source>
        <translation>適用・検証済み</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="378" />
        <source>Putting back what ran before…</source>
        <translation>以前の設定に戻しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="378" />
        <source>Putting back what ran before, over the later change…</source>
        <translation>後からの変更を上書きして、以前の状態に戻しています…</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="395" />
        <source>Undo refused: %1</source>
        <translation>元に戻すことを拒否しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="402" />
        <source>undone</source>
        <translation>元に戻した</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="402" />
        <source>undone anyway (over a later change)</source>
        <translation>後からの変更を上書きして元に戻しました</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="408" />
        <source>the notch from before (%1 Hz, Q %2) is back</source>
        <translation>以前のノッチ (%1 Hz, Q %2) を戻しました</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="409" />
        <source>the notch was removed</source>
        <translation>ノッチを取り除きました</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="411" />
        <source>Undone: %1.</source>
        <translation>元に戻しました: %1。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="413" />
        <source>, and %1</source>
        <translation>。また、%1</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="412" />
        <source>Undone: the gains that ran before are back (read back)%1.</source>
        <translation>元に戻しました: 以前のゲインに戻りました (読み戻し確認)%1。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="392" />
        <source>Undo refused: %1. To put back what ran before all the same, tick the box below and press Undo anyway.</source>
        <translation>元に戻すことを拒否しました: %1。それでも以前の状態に戻すには、下のボックスにチェックを入れて「それでも元に戻す」を押してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="452" />
        <source>Notch f0 [Hz]</source>
        <translation>ノッチ f0 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="452" />
        <location filename="../app/gui/NcPidPage.cpp" line="453" />
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="454" />
        <source>Notch Q</source>
        <translation>ノッチ Q</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="456" />
        <source>Drive input</source>
        <translation>サーボアンプ入力</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="463" />
        <location filename="../app/gui/NcPidPage.cpp" line="468" />
        <source>Crossover [Hz]</source>
        <translation>交差周波数 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="469" />
        <source>Phase margin [°]</source>
        <translation>位相余裕 [°]</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="470" />
        <source>Gain margin [dB]</source>
        <translation>ゲイン余裕 [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="471" />
        <source>Motion time [s]</source>
        <translation>動作時間 [s]</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="483" />
        <source>measured, running gains</source>
        <translation>測定、現在のゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="485" />
        <source>predicted</source>
        <translation>予測</translation>
    </message>
    <message>
        <location filename="../app/gui/NcPidPage.cpp" line="488" />
        <source>verified (measured after applying)</source>
        <translation>検証 (適用後に測定)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NotchProposePage</name>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="335" />
        <source>Resonances and proposed notches</source>
        <translation>共振と提案するノッチフィルタ</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="336" />
        <source>One notch per resonance, within the execution rate's limits; existing filters stay as they are. Edit centre, width or depth: the prediction and the margins follow.</source>
        <translation>共振ごとに 1 つのノッチ (実行周期の制限内)。既存のフィルタはそのまま残します。中心周波数、帯域幅、深さを編集すると、予測と余裕が更新されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="349" />
        <source>Smallest resonance height:</source>
        <translation>共振の最小の高さ:</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="355" />
        <source>Resonance [Hz]</source>
        <translation>共振 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="355" />
        <source>Height [dB]</source>
        <translation>高さ [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="355" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="358" />
        <source>Width [Hz]</source>
        <translation>帯域幅 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="355" />
        <source>Open loop [dB]</source>
        <translation>開ループ [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="358" />
        <source>Slot</source>
        <translation>スロット</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="358" />
        <source>Centre [Hz]</source>
        <translation>中心周波数 [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="358" />
        <source>Depth</source>
        <translation>深さ</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="364" />
        <source>Remove notch</source>
        <translation>ノッチを削除</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="366" />
        <source>Back to the proposal</source>
        <translation>提案に戻す</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="377" />
        <source>Margin</source>
        <translation>余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="377" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="469" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="548" />
        <source>Measured</source>
        <translation>測定値</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="377" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="615" />
        <source>Predicted</source>
        <translation>予測</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="431" />
        <source>No frequency response to analyse.</source>
        <translation>解析する周波数応答がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="479" />
        <source>Reading the existing filters and the execution rate of axis %1…</source>
        <translation>軸 %1 の既存フィルタと実行周期を読み出し中…</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="487" />
        <source>Not connected to axis %1: execution rate %2 Hz assumed, existing filters unknown.</source>
        <translation>軸 %1 に未接続: 実行周波数を %2 Hz と仮定、既存のフィルタは不明。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="500" />
        <source>Reading the parameters failed: %1</source>
        <translation>パラメータの読み出しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="526" />
        <source>Analysing…</source>
        <translation>解析中…</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="579" />
        <source>Row %1: not a number.</source>
        <translation>%1 行目: 数値ではありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="584" />
        <source>Slot %1: edited by the operator (centre %2 Hz, width %3 Hz, depth %4).</source>
        <translation>スロット %1: 作業者が編集 (中心周波数 %2 Hz、帯域幅 %3 Hz、深さ %4)。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="591" />
        <source>Not realisable at %1 Hz: %2</source>
        <translation>%1 Hz では実現できません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="610" />
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="613" />
        <source>N%1 %2 Hz</source>
        <translation>N%1 %2 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="620" />
        <source>%1 resonances found, %2 notches proposed for axis %3 (execution rate %4 Hz, %5 of %6 slots free).</source>
        <translation>共振 %1 個、軸 %3 にノッチ %2 個を提案 (実行周波数 %4 Hz、空きスロット %5 / %6)。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="635" />
        <source>Slot %1 keeps its filter (centre %2 Hz, width %3 Hz, depth %4): existing filters are never removed.</source>
        <translation>スロット %1 はフィルタを維持 (中心周波数 %2 Hz、帯域幅 %3 Hz、深さ %4): 既存のフィルタは削除しません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="641" />
        <source>No notch at %1 Hz: %2</source>
        <translation>%1 Hz にはノッチなし: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="643" />
        <source>Analysis failed: %1</source>
        <translation>解析に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="439" />
        <source>Asking the drive what axis %1 is…</source>
        <translation>軸 %1 の種類をサーボアンプに問い合わせています…</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="39" />
        <source>Axis %1 is a position loop the NC closes with a PID (%2): it has no drive filter slots for this proposal. Next measures its open loop with the gains that run and proposes LinuxCNC's biquad notch after the PID output (net %3).</source>
        <translation>軸 %1 は NC が PID で閉じる位置ループです (%2)。この提案のためのサーボアンプのフィルタスロットはありません。「次へ」で現在のゲインのまま開ループを測定し、PID 出力 (ネット %3) の後に LinuxCNC の biquad ノッチを提案します。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="465" />
        <source>Axis %1: this wizard applies no notch here; why, and what to use instead, is below.</source>
        <translation>軸 %1: このウィザードではここにノッチフィルタを適用できません。理由と代わりに使うものは下に示します。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NotchSavePage</name>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="732" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="733" />
        <source>The session keeps the measured, predicted and verification responses, the resonances, the notches with their rules, the margins, the parameter sets and the journal.</source>
        <translation>セッションには、測定・予測・検証の応答、共振、ノッチとそのルール、余裕、パラメータセット、変更履歴が保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="746" />
        <source>Session %1 saved (kind “notch”).</source>
        <translation>セッション %1 を保存しました (種類 “notch”)。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="747" />
        <source>The session could not be saved (see the log).</source>
        <translation>セッションを保存できませんでした (ログを参照)。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="749" />
        <source>%1 notches applied to axis %2 and read back.</source>
        <translation>軸 %2 にノッチ %1 個を適用し、読み出して確認しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="750" />
        <source>The notches were not applied; the proposal is kept in the session.</source>
        <translation>ノッチは適用されていません。提案はセッションに保存されます。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NotchSourcePage</name>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="171" />
        <source>Frequency response</source>
        <translation>周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="172" />
        <source>The notches are placed on a measured velocity-loop frequency response: measure a new one, or take one from a saved session of this machine.</source>
        <translation>ノッチは測定した速度ループの周波数応答をもとに配置します: 新しく測定するか、この機械の保存済みセッションから選んでください。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="175" />
        <source>New measurement (multi-sweep, up to just below the trace rate)</source>
        <translation>新しい測定 (複数回掃引、トレース周波数の直下まで)</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="177" />
        <source>Frequency response from a saved session</source>
        <translation>保存済みセッションの周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="181" />
        <source>Measurement</source>
        <translation>測定</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="193" />
        <source>0.975 × trace rate</source>
        <translation>0.975 × トレース周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="202" />
        <source> % of rated torque</source>
        <translation> % (定格トルク比)</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="203" />
        <source>Lowest frequency:</source>
        <translation>最低周波数:</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="204" />
        <source>Highest frequency:</source>
        <translation>最高周波数:</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="205" />
        <source>Frequencies (log-spaced):</source>
        <translation>周波数点数 (対数間隔):</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="206" />
        <source>Amplitude:</source>
        <translation>振幅:</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="240" />
        <source>Axis %1 is a position loop the NC closes with a PID (%2). A new measurement measures its open loop and proposes LinuxCNC's biquad notch after the PID output (net %3) for the gains that run.</source>
        <translation>軸 %1 は NC が PID で閉じる位置ループです (%2)。新しい測定では開ループを測定し、現在のゲインに対して PID 出力 (ネット %3) の後に LinuxCNC の biquad ノッチを提案します。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="253" />
        <source>No store is open: only a new measurement is possible.</source>
        <translation>データベースが開かれていません: 新しい測定のみ可能です。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="258" />
        <source>Reading the sessions failed: %1</source>
        <translation>セッションの読み出しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="270" />
        <source>Session %1 (%2, axis %3, %4): %5</source>
        <translation>セッション %1 (%2、軸 %3、%4): %5</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="280" />
        <source>No saved session of this machine holds a frequency response.</source>
        <translation>この機械の保存済みセッションに周波数応答はありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="304" />
        <source>Reading session %1 failed: %2</source>
        <translation>セッション %1 の読み出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="312" />
        <source>Session %1, %2: %3</source>
        <translation>セッション %1、%2: %3</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NotchVerifyPage</name>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="674" />
        <source>Verification</source>
        <translation>検証</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="675" />
        <source>The new measurement with the notches, overlaid on the prediction and on the first measurement.</source>
        <translation>ノッチを入れた新しい測定を、予測および最初の測定に重ねて表示します。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="686" />
        <source>Notch [Hz]</source>
        <translation>ノッチ [Hz]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="686" />
        <source>Before [dB]</source>
        <translation>適用前 [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="686" />
        <source>Predicted [dB]</source>
        <translation>予測 [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="686" />
        <source>Measured [dB]</source>
        <translation>測定 [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="688" />
        <source>Margin</source>
        <translation>余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="688" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="698" />
        <source>Before</source>
        <translation>適用前</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="688" />
        <location filename="../app/gui/NotchWizardPages.cpp" line="699" />
        <source>Predicted</source>
        <translation>予測</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="688" />
        <source>Measured</source>
        <translation>測定値</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="700" />
        <source>After</source>
        <translation>適用後</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="703" />
        <source>N%1</source>
        <translation>N%1</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="707" />
        <source>No point of the verification could be compared with the prediction.</source>
        <translation>検証の点のうち、予測と比較できるものがありませんでした。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizardPages.cpp" line="708" />
        <source>Prediction against measurement: largest deviation %1 dB at %2 Hz, rms %3 dB, over %4 valid points from %5 Hz to %6 Hz (points where both lie below −50 dB are left out).</source>
        <translation>予測と測定の比較: 最大偏差 %1 dB (%2 Hz)、rms %3 dB、%5 Hz から %6 Hz の有効な %4 点 (両方が −50 dB 未満の点は除外)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::NotchWizard</name>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="61" />
        <source>Notch filters</source>
        <translation>ノッチフィルタ</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="72" />
        <source>A multi-sweep frequency-response test: a sinusoidal torque of the chosen amplitude (in % of the rated torque) is added to the velocity controller's output at each frequency of the band, three times with phase offsets of 0°, +120° and −120°, while the velocity loop holds the axis. The axis vibrates a little around its position; it does not travel.</source>
        <translation>複数回掃引の周波数応答テスト: 速度ループが軸を保持した状態で、帯域の各周波数で、選んだ振幅 (定格トルク比 %) の正弦波トルクを速度制御器の出力に、位相オフセット 0°、+120°、−120° で 3 回加えます。軸は現在位置の周りでわずかに振動しますが、移動はしません。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="80" />
        <source>Measure the frequency response</source>
        <translation>周波数応答を測定</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="85" />
        <source>Apply the notch filters</source>
        <translation>ノッチフィルタを適用</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="88" />
        <source>Verify: measure again with the notches</source>
        <translation>検証: ノッチを入れて再測定</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="131" />
        <source>the notch filters</source>
        <translation>ノッチフィルタ</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="419" />
        <source>The session could not be saved: %1</source>
        <translation>セッションを保存できませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="420" />
        <source>Stopped: %1 Session %2 saved as aborted.</source>
        <translation>停止: %1 セッション %2 を中止として保存しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/NotchWizard.cpp" line="421" />
        <source>Session %1 saved.</source>
        <translation>セッション %1 を保存しました。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::ParameterInspector</name>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="92" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="92" />
        <source>Device</source>
        <translation>サーボアンプ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="92" />
        <source>Profile</source>
        <translation>プロファイル</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="92" />
        <source>Proposed</source>
        <translation>提案値</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="92" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="92" />
        <source>Limits</source>
        <translation>範囲</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="93" />
        <source>No axis selected</source>
        <translation>軸が選択されていません</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="94" />
        <source>Machine %1, axis %2</source>
        <translation>機械 %1、軸 %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="94" />
        <source>(none)</source>
        <translation>(なし)</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="95" />
        <source>Current parameters of the profile in the store</source>
        <translation>データベースにあるプロファイルの現在のパラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="96" />
        <source>Values proposed by a wizard, not yet applied</source>
        <translation>ウィザードが提案した未適用の値</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="160" />
        <source>Reading the parameter list of axis %1 failed: %2</source>
        <translation>軸 %1 のパラメータ一覧の読み出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="167" />
        <source>Reading the parameters of axis %1 failed: %2</source>
        <translation>軸 %1 のパラメータの読み出しに失敗しました: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="217" />
        <source>Differs from the device value</source>
        <translation>サーボアンプの値と異なります</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="228" />
        <source>%1 … %2%3</source>
        <translation>%1 … %2%3</translation>
    </message>
    <message>
        <location filename="../app/gui/ParameterInspector.cpp" line="229" />
        <source> (read-only)</source>
        <translation> (読み出し専用)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::ReportDialog</name>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="24" />
        <source>Report of session %1</source>
        <translation>セッション %1 のレポート</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="30" />
        <source>Save as HTML…</source>
        <translation>HTML で保存…</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="32" />
        <source>Save as PDF…</source>
        <translation>PDF で保存…</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="34" />
        <source>Close</source>
        <translation>閉じる</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="56" />
        <source>Save report as PDF</source>
        <translation>レポートを PDF で保存</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="56" />
        <source>Save report as HTML</source>
        <translation>レポートを HTML で保存</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="57" />
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="57" />
        <source>HTML (*.html *.htm)</source>
        <translation>HTML (*.html *.htm)</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="64" />
        <source>Report not saved</source>
        <translation>レポートは保存されませんでした</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="67" />
        <source>Saved %1</source>
        <translation>%1 を保存しました</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="75" />
        <source>No store is open.</source>
        <translation>データベースが開かれていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="77" />
        <source>Session %1 cannot be loaded: %2</source>
        <translation>セッション %1 を読み込めません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ReportDialog.cpp" line="87" />
        <source>No report</source>
        <translation>レポートなし</translation>
    </message>
</context>
<context>
    <name>axistune::gui::SafetyPage</name>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="129" />
        <source>Safety</source>
        <translation>安全確認</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="130" />
        <source>Check the axis and its limits before anything moves.</source>
        <translation>動かす前に、軸とその制限を確認してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="134" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="139" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="139" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="139" />
        <source>Limits</source>
        <translation>範囲</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="139" />
        <source>Unit</source>
        <translation>単位</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="144" />
        <source>The axis is free to move over the whole test, nobody is inside the machine, and the emergency stop is within reach.</source>
        <translation>テスト全体を通じて軸は自由に動くことができ、機械の中には誰もおらず、非常停止ボタンに手が届きます。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="181" />
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="186" />
        <source>Reading the limits failed: %1</source>
        <translation>制限値の読み出しに失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="206" />
        <source>Not connected: connect to a machine first (Machine ▸ Connect).</source>
        <translation>未接続: 先に機械に接続してください (機械 ▸ 接続)。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="208" />
        <source>Machine %1, connected through %2.</source>
        <translation>機械 %1、%2 で接続中。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::ScopeDock</name>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="541" />
        <source>Stopped</source>
        <translation>停止中</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="543" />
        <source>Armed: filling the pre-trigger</source>
        <translation>待機中: プリトリガを記録中</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="545" />
        <source>Waiting for the trigger</source>
        <translation>トリガ待ち</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="547" />
        <source>Triggered</source>
        <translation>トリガ成立</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="549" />
        <source>Capture complete</source>
        <translation>記録完了</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="551" />
        <source>Rolling</source>
        <translation>ロール表示中</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="553" />
        <source>Offline review</source>
        <translation>オフライン表示</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="84" />
        <source>Connection lost: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="295" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="296" />
        <source>Trigger</source>
        <translation>トリガ</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="297" />
        <source>Channel:</source>
        <translation>チャンネル:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="298" />
        <source>Level:</source>
        <translation>レベル:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="299" />
        <source>Edge:</source>
        <translation>エッジ:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="300" />
        <source>rising</source>
        <translation>立ち上がり</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="301" />
        <source>falling</source>
        <translation>立ち下がり</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="302" />
        <source>either</source>
        <translation>両エッジ</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="303" />
        <source>Pre-trigger:</source>
        <translation>プリトリガ:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="304" />
        <source>Length:</source>
        <translation>記録長:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="305" />
        <source>Divider:</source>
        <translation>分周比:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="306" />
        <source>Roll mode</source>
        <translation>ロールモード</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="307" />
        <source>Roll (continuous, no trigger)</source>
        <translation>ロール (連続記録、トリガなし)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="308" />
        <source>History:</source>
        <translation>履歴:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="309" />
        <source> samples per channel</source>
        <translation> サンプル/チャンネル</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="310" />
        <source>Shown while rolling:</source>
        <translation>ロール中の表示幅:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="325" />
        <location filename="../app/gui/ScopeDockUi.cpp" line="330" />
        <source>Jog</source>
        <translation>ジョグ</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="326" />
        <source>Distance:</source>
        <translation>移動量:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="327" />
        <source>Speed:</source>
        <translation>速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="328" />
        <source>Acceleration:</source>
        <translation>加速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="329" />
        <source>Back and forth (return to the start)</source>
        <translation>往復 (始点に戻る)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="331" />
        <source>Stop jog</source>
        <translation>ジョグ停止</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="332" />
        <source>Run</source>
        <translation>実行</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="333" />
        <source>Triggered captures one after the other (normal mode), or roll mode when it is ticked</source>
        <translation>トリガ記録を繰り返します (ノーマルモード)。ロールにチェックがあればロールモードで記録します</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="334" />
        <source>Single</source>
        <translation>シングル</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="335" />
        <source>One triggered capture, then the scope stops</source>
        <translation>トリガ記録を 1 回行い、スコープを停止します</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="336" />
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="337" />
        <source>Export CSV…</source>
        <translation>CSV 書き出し…</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="338" />
        <source>Export image…</source>
        <translation>画像書き出し…</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="339" />
        <source>Save to store</source>
        <translation>ストアに保存</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="340" />
        <source>Open saved…</source>
        <translation>保存した記録を開く…</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="341" />
        <source>Open CSV…</source>
        <translation>CSV を開く…</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="170" />
        <source>The drive offers no scope on axis %1: %2</source>
        <translation>軸 %1 のドライブにはスコープがありません: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="268" />
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="268" />
        <source> deg</source>
        <translation> deg</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="269" />
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="269" />
        <source> deg/s</source>
        <translation> deg/s</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="270" />
        <source> mm/s²</source>
        <translation> mm/s²</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="270" />
        <source> deg/s²</source>
        <translation> deg/s²</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="276" />
        <source>Sample rate: (no scope)</source>
        <translation>サンプリング周波数: (スコープなし)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="280" />
        <source>Sample rate: %1 Hz (drive's fastest %2 Hz / %3)</source>
        <translation>サンプリング周波数: %1 Hz (ドライブの最速 %2 Hz / %3)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="322" />
        <source>The drive's scope channels are not known yet (axis %1)</source>
        <translation>ドライブのスコープのチャンネルをまだ取得していません (軸 %1)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="328" />
        <source>Channels: tick at least one channel</source>
        <translation>チャンネル: 少なくとも 1 つのチャンネルにチェックを入れてください</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="338" />
        <source>Trigger channel: choose one of the ticked channels</source>
        <translation>トリガチャンネル: チェックしたチャンネルから選んでください</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="346" />
        <source>Length: %1 s is shorter than two samples at %2 Hz</source>
        <translation>記録長: %1 s は %2 Hz の 2 サンプルより短いです</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="377" />
        <source>Scope armed on axis %1: %2, %3 channels</source>
        <translation>軸 %1 のスコープを開始: %2、%3 チャンネル</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="378" />
        <source>roll mode</source>
        <translation>ロールモード</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="378" />
        <source>single capture</source>
        <translation>シングル記録</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="378" />
        <source>normal mode</source>
        <translation>ノーマルモード</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="389" />
        <source>The drive refused the scope: %1</source>
        <translation>ドライブがスコープの設定を拒否しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="390" />
        <source>Scope: %1</source>
        <translation>スコープ: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="434" />
        <location filename="../app/gui/ScopeDock.cpp" line="435" />
        <source>Scope stopped: %1</source>
        <translation>スコープが停止しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="449" />
        <source>%1 samples were lost (overwritten in the drive before they were read); the gaps are in the sample numbers</source>
        <translation>%1 サンプルが失われました (読み出す前にドライブ内で上書きされました)。欠落はサンプル番号に現れます</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="466" />
        <source>Scope capture %1 on axis %2: %3 samples, trigger at sample %4</source>
        <translation>スコープ記録 %1 (軸 %2): %3 サンプル、トリガはサンプル %4</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="68" />
        <source>No capture to export</source>
        <translation>書き出す記録がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="92" />
        <source>Export the capture as CSV</source>
        <translation>記録を CSV に書き出し</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="93" />
        <location filename="../app/gui/ScopeDockFiles.cpp" line="242" />
        <source>Scope CSV (*.csv)</source>
        <translation>スコープ CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="98" />
        <location filename="../app/gui/ScopeDockFiles.cpp" line="111" />
        <source>Written: %1</source>
        <translation>書き出しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="105" />
        <source>Export the plot</source>
        <translation>グラフの書き出し</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="106" />
        <source>Images (*.png *.svg *.pdf)</source>
        <translation>画像 (*.png *.svg *.pdf)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="120" />
        <source>No capture to save</source>
        <translation>保存する記録がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="125" />
        <location filename="../app/gui/ScopeDockFiles.cpp" line="157" />
        <source>No store is open (Settings → Preferences)</source>
        <translation>ストアが開かれていません (設定 → 環境設定)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="140" />
        <source>Capture saved in the store as session %1</source>
        <translation>記録をセッション %1 としてストアに保存しました</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="143" />
        <source>The capture was not saved: %1</source>
        <translation>記録は保存されませんでした: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="166" />
        <source>Session %1: %2</source>
        <translation>セッション %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="171" />
        <source>store session %1</source>
        <translation>ストアのセッション %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="174" />
        <source>Session %1 (%2, axis %3) from the store</source>
        <translation>ストアのセッション %1 (%2、軸 %3)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="179" />
        <source>Session %1 holds no scope capture</source>
        <translation>セッション %1 にはスコープの記録がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="196" />
        <source>Session %1: %2, axis %3, %4</source>
        <translation>セッション %1: %2、軸 %3、%4</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="200" />
        <source>The store holds no scope capture</source>
        <translation>ストアにスコープの記録がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="205" />
        <source>Open a saved capture</source>
        <translation>保存した記録を開く</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="205" />
        <source>Capture:</source>
        <translation>記録:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="235" />
        <source>Opened %1</source>
        <translation>%1 を開きました</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockFiles.cpp" line="242" />
        <source>Open a scope CSV</source>
        <translation>スコープ CSV を開く</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="592" />
        <source>Jog: not connected</source>
        <translation>ジョグ: 接続されていません</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="607" />
        <source>Jog on axis %1: %2 at %3%4</source>
        <translation>軸 %1 のジョグ: %2、速度 %3%4</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="609" />
        <source>, back and forth</source>
        <translation>、往復</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDock.cpp" line="627" />
        <source>Jog: %1</source>
        <translation>ジョグ: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="311" />
        <source>Math, spectrum and XY</source>
        <translation>演算、スペクトル、XY</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="312" />
        <source>Math channel:</source>
        <translation>演算チャンネル:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="313" />
        <location filename="../app/gui/ScopeDockUi.cpp" line="319" />
        <source>none</source>
        <translation>なし</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="314" />
        <source>A − B</source>
        <translation>A − B</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="315" />
        <source>d/dt A</source>
        <translation>d/dt A</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="316" />
        <source>Scale:</source>
        <translation>スケール:</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="317" />
        <source>Shows this channel as gain × value + offset (the offset in the channel's unit); exports and the store keep the drive's values</source>
        <translation>このチャンネルをゲイン × 値 + オフセット(オフセットはチャンネルの単位)で表示します。書き出しとストアにはドライブの値がそのまま残ります</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="320" />
        <source>Spectrum of A (visible window)</source>
        <translation>A のスペクトル (表示範囲)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="321" />
        <source>XY plot (Y against X)</source>
        <translation>XY 表示 (X に対する Y)</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="322" />
        <source>Keep as reference</source>
        <translation>基準として残す</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="323" />
        <source>Overlays the capture shown, dashed, under the next captures</source>
        <translation>表示中の記録を破線で次の記録に重ねて表示します</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockUi.cpp" line="324" />
        <source>Clear references</source>
        <translation>基準を消去</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockAnalysis.cpp" line="152" />
        <source>capture</source>
        <translation>記録</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockAnalysis.cpp" line="194" />
        <source>ref %1: %2</source>
        <translation>基準 %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockAnalysis.cpp" line="214" />
        <source>No capture shown</source>
        <translation>表示中の記録がありません</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockAnalysis.cpp" line="230" />
        <source>Frequency</source>
        <translation>周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockAnalysis.cpp" line="230" />
        <source>Amplitude</source>
        <translation>振幅</translation>
    </message>
    <message>
        <location filename="../app/gui/ScopeDockAnalysis.cpp" line="234" />
        <source>Spectrum of %1 (%2 samples, %3 Hz resolution)</source>
        <translation>%1 のスペクトル (%2 サンプル、分解能 %3 Hz)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::SessionOverlay</name>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="304" />
        <source>session %1: %2</source>
        <translation>セッション %1: %2</translation>
    </message>
</context>
<context>
    <name>axistune::gui::SessionReview</name>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="97" />
        <source>Machine:</source>
        <translation>機械:</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="99" />
        <location filename="../app/gui/SessionReview.cpp" line="124" />
        <source>(all machines)</source>
        <translation>(すべての機械)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="100" />
        <source>Reload</source>
        <translation>再読み込み</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="101" />
        <source>Open</source>
        <translation>開く</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="102" />
        <source>Shows the selected session read-only with all its plots</source>
        <translation>選択したセッションをすべてのプロットとともに読み取り専用で表示します</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="103" />
        <source>Overlay responses</source>
        <translation>応答を重ねて表示</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="104" />
        <source>One Bode plot with the frequency responses of every selected session</source>
        <translation>選択したすべてのセッションの周波数応答を 1 つのボード線図に表示します</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="106" />
        <source>Report…</source>
        <translation>レポート…</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="107" />
        <source>Id</source>
        <translation>ID</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="107" />
        <source>Kind</source>
        <translation>種類</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="107" />
        <source>Status</source>
        <translation>状態</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="107" />
        <source>Started (UTC)</source>
        <translation>開始 (UTC)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="107" />
        <source>Operator</source>
        <translation>作業者</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="107" />
        <source>Note</source>
        <translation>メモ</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="108" />
        <source>Captures</source>
        <translation>計測データ</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="108" />
        <source>Results</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="151" />
        <source>Listing the sessions failed: %1</source>
        <translation>セッションの一覧の取得に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="158" />
        <source>completed</source>
        <translation>完了</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="159" />
        <source>ABORTED</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="160" />
        <source>FAILED</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="237" />
        <location filename="../app/gui/SessionReview.cpp" line="256" />
        <source>Session %1 could not be loaded: %2</source>
        <translation>セッション %1 を読み込めませんでした: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="242" />
        <source>Session %1 (%2)</source>
        <translation>セッション %1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReview.cpp" line="265" />
        <source>Sessions %1</source>
        <translation>セッション %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::SessionView</name>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="114" />
        <source>&lt;b&gt;Session %1&lt;/b&gt; — %2, machine %3, axis %4, %5 … %6, operator %7, status %8%9</source>
        <translation>&lt;b&gt;セッション %1&lt;/b&gt; — %2、機械 %3、軸 %4、%5 … %6、作業者 %7、状態 %8%9</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="117" />
        <source>(none)</source>
        <translation>(なし)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="121" />
        <source>&lt;br&gt;Note: %1</source>
        <translation>&lt;br&gt;メモ: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="127" />
        <source>Export captures as CSV…</source>
        <translation>計測データを CSV で書き出し…</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="128" />
        <source>Export plots…</source>
        <translation>プロットを書き出し…</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="150" />
        <source>Frequency response</source>
        <translation>周波数応答</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="162" />
        <source>Trace: %1</source>
        <translation>トレース: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="172" />
        <source>Key</source>
        <translation>キー</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="172" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="174" />
        <source>inputs</source>
        <translation>入力</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="176" />
        <source>result: %1</source>
        <translation>結果: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="180" />
        <source>[%1 values]</source>
        <translation>[%1 個の値]</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="184" />
        <source>Inputs and results</source>
        <translation>入力と結果</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="186" />
        <location filename="../app/gui/SessionReviewView.cpp" line="194" />
        <source>Axis</source>
        <translation>軸</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="186" />
        <source>Source</source>
        <translation>出所</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="186" />
        <location filename="../app/gui/SessionReviewView.cpp" line="194" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="186" />
        <location filename="../app/gui/SessionReviewView.cpp" line="194" />
        <source>Parameter</source>
        <translation>パラメータ</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="186" />
        <source>Value (SI)</source>
        <translation>値 (SI)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="186" />
        <source>Note</source>
        <translation>メモ</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="192" />
        <source>Parameter sets</source>
        <translation>パラメータセット</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="194" />
        <source>Old (SI)</source>
        <translation>旧値 (SI)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="194" />
        <source>New (SI)</source>
        <translation>新値 (SI)</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="198" />
        <source>not recorded</source>
        <translation>記録なし</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="200" />
        <source>Journal</source>
        <translation>変更履歴</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="264" />
        <source>Export captures to</source>
        <translation>計測データの書き出し先</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="270" />
        <location filename="../app/gui/SessionReviewView.cpp" line="287" />
        <source>Export failed</source>
        <translation>書き出しに失敗しました</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="272" />
        <location filename="../app/gui/SessionReviewView.cpp" line="289" />
        <source>Export</source>
        <translation>書き出し</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/SessionReviewView.cpp" line="272" />
        <location filename="../app/gui/SessionReviewView.cpp" line="289" />
        <source>%n file(s) written to %1</source>
        <translation>
            <numerusform>%1 に %n 個のファイルを書き出しました</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="277" />
        <source>Export plots to</source>
        <translation>プロットの書き出し先</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="281" />
        <source>Image format</source>
        <translation>画像形式</translation>
    </message>
    <message>
        <location filename="../app/gui/SessionReviewView.cpp" line="281" />
        <source>Format:</source>
        <translation>形式:</translation>
    </message>
</context>
<context>
    <name>axistune::gui::SettingsDialog</name>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="123" />
        <source>Preferences</source>
        <translation>環境設定</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="124" />
        <source>Language:</source>
        <translation>言語:</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="125" />
        <source>Store file:</source>
        <translation>データベースファイル:</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="126" />
        <source>Browse…</source>
        <translation>参照…</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="127" />
        <source>Operator name:</source>
        <translation>作業者名:</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="128" />
        <source>The SQLite file holding machines, profiles, sessions and the journal</source>
        <translation>機械、プロファイル、セッション、変更履歴を保存する SQLite ファイル</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="142" />
        <source>Store file</source>
        <translation>データベースファイル</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="142" />
        <source>AxisTune store (*.sqlite)</source>
        <translation>AxisTune データベース (*.sqlite)</translation>
    </message>
    <message>
        <location filename="../app/gui/SettingsDialog.cpp" line="153" />
        <source>The Japanese translation could not be loaded</source>
        <translation>日本語の翻訳を読み込めませんでした</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TestRunPage</name>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="230" />
        <source>Run</source>
        <translation>実行</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="231" />
        <source>The axis moves now. Abort stops the motion at once and restores the parameters.</source>
        <translation>軸が動きます。中止すると動作は直ちに止まり、パラメータは元に戻ります。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="241" />
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="243" />
        <source>Run again</source>
        <translation>再実行</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="254" />
        <location filename="../app/gui/WizardPages.cpp" line="256" />
        <source>Connection lost: %1</source>
        <translation>接続が切れました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="289" />
        <source>Nothing to run.</source>
        <translation>実行するものがありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="293" />
        <source>Not connected.</source>
        <translation>未接続です。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="308" />
        <source>Test %1 of %2 on axis %3: %4</source>
        <translation>テスト %1 / %2、軸 %3: %4</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="329" />
        <source>Abort requested</source>
        <translation>中止を要求しました</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="360" />
        <source>Completed.</source>
        <translation>完了しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="360" />
        <source>Aborted: %1</source>
        <translation>中止: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/WizardPages.cpp" line="361" />
        <source>Failed: %1</source>
        <translation>失敗: %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TwoInertiaFilterPage</name>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="362" />
        <source>Suppression filter and predicted load error</source>
        <translation>振動抑制フィルタと負荷側誤差の予測</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="363" />
        <source>Semi-closed: F_m = (s² + 2ζω₀s + ω₀²)/(2ζω₀s + ω₀²) on the position command (5.7). Full-closed: F_L = F_m/(τs + 1) on the velocity command (5.9). Start values from the model: f₀ and the zero damping ζ₀ (not ζ_p). The drive's position.feedback decides which filter it runs.</source>
        <translation>セミクローズド: 位置指令に F_m = (s² + 2ζω₀s + ω₀²)/(2ζω₀s + ω₀²) (5.7)。フルクローズド: 速度指令に F_L = F_m/(τs + 1) (5.9)。初期値はモデルから: f₀ と零点の減衰比 ζ₀ (ζ_p ではありません)。どちらのフィルタを使うかはサーボアンプの position.feedback で決まります。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="371" />
        <source>Semi-closed (F_m)</source>
        <translation>セミクローズド (F_m)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="371" />
        <source>Full-closed (F_L)</source>
        <translation>フルクローズド (F_L)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="373" />
        <source>0: high-frequency gain 1/(2ζω₀τ) = 2.5</source>
        <translation>0: 高周波ゲイン 1/(2ζω₀τ) = 2.5</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="377" />
        <source>Feedback:</source>
        <translation>フィードバック:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="378" />
        <source>F_L time constant τ:</source>
        <translation>F_L の時定数 τ:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="379" />
        <source>Profile speed:</source>
        <translation>プロファイルの速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="380" />
        <source>Acceleration:</source>
        <translation>加速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="381" />
        <source>Jerk:</source>
        <translation>加加速度:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="383" />
        <source>Setting</source>
        <translation>設定</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="383" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="390" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="390" />
        <source>Load error y_L − y*</source>
        <translation>負荷側誤差 y_L − y*</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="423" />
        <source>Set by the axis's position.feedback</source>
        <translation>軸の position.feedback で決まります</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="459" />
        <source>without filter</source>
        <translation>フィルタなし</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="460" />
        <source>with F_m</source>
        <translation>F_m あり</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="465" />
        <source>Filter frequency f₀</source>
        <translation>フィルタ周波数 f₀</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="465" />
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="466" />
        <source>Filter damping ζ</source>
        <translation>フィルタの減衰 ζ</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="468" />
        <source>Time constant τ</source>
        <translation>時定数 τ</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="468" />
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="469" />
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="469" />
        <source>First-order lag T₁ = 2ζ/ω₀</source>
        <translation>1 次遅れ T₁ = 2ζ/ω₀</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="470" />
        <source>Velocity K_P (TI-5, ω_l 24 Hz, k 10)</source>
        <translation>速度 K_P (TI-5、ω_l 24 Hz、k 10)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="472" />
        <source>Velocity K_I (TI-5)</source>
        <translation>速度 K_I (TI-5)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="473" />
        <source>Drive filter suppression.mode</source>
        <translation>サーボアンプのフィルタ suppression.mode</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="474" />
        <source>2 (full-closed F_L)</source>
        <translation>2 (フルクローズド F_L)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="474" />
        <source>1 (semi-closed F_m)</source>
        <translation>1 (セミクローズド F_m)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="475" />
        <source>Torque feedforward inertia J_m + J_L</source>
        <translation>トルクフィードフォワードのイナーシャ J_m + J_L</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="478" />
        <source>Predicted maximum load error: %1° without the filter, %2° with F_m (ideal motor tracking, load through (5.6)).</source>
        <translation>負荷側誤差の最大値の予測: フィルタなし %1°、F_m あり %2° (モータは理想追従、負荷は (5.6) で計算)。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="483" />
        <source>F_L acts inside the full-closed loop: the prediction with the filter is the semi-closed one.</source>
        <translation>F_L はフルクローズドのループ内で働くため、フィルタありの予測はセミクローズドのものです。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="484" />
        <source>The proposal writes the filter to the drive (suppression.mode, f0, zeta%1), the velocity PI of the thesis rule K_P = k√2·ω_l·J_m, K_I = k·ω_l²·J_m on the fitted J_m, and the velocity and torque feedforward the method needs. The profile runs once before and once after the change.</source>
        <translation>提案では、フィルタ (suppression.mode、f0、zeta%1) をサーボアンプに書き込み、同定した J_m に論文の規則 K_P = k√2·ω_l·J_m、K_I = k·ω_l²·J_m による速度 PI と、この手法に必要な速度・トルクフィードフォワードを適用します。プロファイルは変更の前と後に 1 回ずつ実行します。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="489" />
        <source>Not connected to the axis: the mode is chosen here, and the settings are only stored.</source>
        <translation>軸に接続されていません: モードはここで選択し、設定は保存のみ行います。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TwoInertiaFitPage</name>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="164" />
        <source>Two-inertia model</source>
        <translation>2慣性系モデル</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="165" />
        <source>Torque → motor velocity P_m with the fitted model (5.1) over it: anti-resonance f₀ = √(K/J_L)/2π (zero), resonance f_p = √(K(1/J_m + 1/J_L))/2π (pole), and the residual model/measured.</source>
        <translation>トルク → モータ速度 P_m と、それに重ねた同定モデル (5.1): 反共振 f₀ = √(K/J_L)/2π (零点)、共振 f_p = √(K(1/J_m + 1/J_L))/2π (極)、およびモデル/測定の残差。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="174" />
        <source>Frequency</source>
        <translation>周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="174" />
        <source>Residual model/measured</source>
        <translation>残差 モデル/測定</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="174" />
        <source>dB, °</source>
        <translation>dB, °</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="179" />
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="179" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="204" />
        <source>No response to fit.</source>
        <translation>同定する応答がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="209" />
        <source>Fitting…</source>
        <translation>同定中…</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="301" />
        <source>measured P_m</source>
        <translation>測定した P_m</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="303" />
        <source>Fit failed: %1</source>
        <translation>同定に失敗しました: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="320" />
        <source>two-inertia model</source>
        <translation>2慣性系モデル</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="324" />
        <source>f₀ %1 Hz, ζ₀ %2</source>
        <translation>f₀ %1 Hz、ζ₀ %2</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="326" />
        <source>f_p %1 Hz, ζ_p %2</source>
        <translation>f_p %1 Hz、ζ_p %2</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="328" />
        <source>magnitude [dB]</source>
        <translation>ゲイン [dB]</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="329" />
        <source>phase [°]</source>
        <translation>位相 [°]</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="331" />
        <source>Anti-resonance f₀</source>
        <translation>反共振 f₀</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="331" />
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="333" />
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="332" />
        <source>Zero damping ζ₀</source>
        <translation>零点の減衰 ζ₀</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="333" />
        <source>Resonance f_p</source>
        <translation>共振 f_p</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="334" />
        <source>Pole damping ζ_p</source>
        <translation>極の減衰 ζ_p</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="335" />
        <source>Motor inertia J_m</source>
        <translation>モータ側イナーシャ J_m</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="336" />
        <source>Load inertia J_L</source>
        <translation>負荷側イナーシャ J_L</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="337" />
        <source>Stiffness K</source>
        <translation>剛性 K</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="338" />
        <source>Damping C</source>
        <translation>減衰 C</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="339" />
        <source>Delay</source>
        <translation>遅れ</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="340" />
        <source>Fit error (rms relative)</source>
        <translation>同定誤差 (相対 rms)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="341" />
        <source>Check f_p/f₀ = √(1 + J_L/J_m)</source>
        <translation>確認 f_p/f₀ = √(1 + J_L/J_m)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="342" />
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="344" />
        <source>Fit over %1–%2 Hz, %3 points, %4 iterations. The response was converted from the closed velocity loop with K_P %5 N·m·s/rad, K_I %6 N·m/rad when it was one.</source>
        <translation>%1–%2 Hz で同定、%3 点、反復 %4 回。速度閉ループの応答の場合は K_P %5 N·m·s/rad、K_I %6 N·m/rad で変換しました。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TwoInertiaSavePage</name>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="54" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="55" />
        <source>The session holds the measured response, the plant, the fitted model, the filter settings, the predicted load error, what was applied with its journal, and the verification.</source>
        <translation>セッションには、測定した応答、プラント、同定モデル、フィルタ設定、負荷側誤差の予測、適用した内容とその履歴、検証が保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="75" />
        <source>Axis %1: anti-resonance f₀ %2 Hz, resonance f_p %3 Hz; filter %4: f₀ %5 Hz, ζ %6%7.</source>
        <translation>軸 %1: 反共振 f₀ %2 Hz、共振 f_p %3 Hz; フィルタ %4: f₀ %5 Hz、ζ %6%7。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="79" />
        <source>F_L (full-closed)</source>
        <translation>F_L (フルクローズド)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="79" />
        <source>F_m (semi-closed)</source>
        <translation>F_m (セミクローズド)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="83" />
        <source>, τ %1 ms</source>
        <translation>、τ %1 ms</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="87" />
        <source>Maximum load error of the profile: measured %1° with the filter (%2° before the change); predicted %3° without and %4° with the filter.</source>
        <translation>プロファイルでの負荷側誤差の最大値: 測定値はフィルタあり %1° (変更前 %2°)、予測値はフィルタなし %3°、フィルタあり %4° です。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="94" />
        <source>Not connected: applying the filter and verifying with the profile need a connection.</source>
        <translation>未接続です: フィルタの適用とプロファイルでの検証には接続が必要です。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="96" />
        <source>Not applied: the proposal is kept in the session.</source>
        <translation>未適用: 提案はセッションに保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="97" />
        <source>Saved as session %1.</source>
        <translation>セッション %1 として保存しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="98" />
        <source>The session was not saved (no store open).</source>
        <translation>セッションは保存されませんでした (データベースが開かれていません)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TwoInertiaSourcePage</name>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="56" />
        <source>Two-inertia: low-frequency response</source>
        <translation>2慣性系: 低周波の応答</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="57" />
        <source>Measure the response of the velocity loop in the low band (torque injection, multi-sweep) or take a response from a saved session. The fit needs the anti-resonance and the resonance inside the band (thesis: 5–300 Hz).</source>
        <translation>低い帯域で速度ループの応答を測定するか (トルク注入、複数回掃引)、保存済みセッションの応答を使ってください。同定には帯域内に反共振と共振が必要です (論文: 5–300 Hz)。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="62" />
        <source>Measure on the machine</source>
        <translation>機械で測定</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="64" />
        <source>From a saved session</source>
        <translation>保存済みセッションから</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="77" />
        <source>Band from:</source>
        <translation>帯域 下限:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="78" />
        <source>to:</source>
        <translation>上限:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="79" />
        <source>Frequencies (log-spaced):</source>
        <translation>周波数点数 (対数間隔):</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="80" />
        <source>Injection amplitude (of rated torque):</source>
        <translation>注入振幅 (定格トルク比):</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="86" />
        <source>Velocity loop of the measurement (read from the drive when connected)</source>
        <translation>測定時の速度ループ (接続中はサーボアンプから読み出し)</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="90" />
        <source>K_P:</source>
        <translation>K_P:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="91" />
        <source>K_I:</source>
        <translation>K_I:</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="109" />
        <source>Session %1: %2, %3 axis %4, %5</source>
        <translation>セッション %1: %2、%3 軸 %4、%5</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="120" />
        <source>Not connected: only saved responses can be used; apply and verify need a connection.</source>
        <translation>未接続: 保存済みの応答のみ使用できます。適用と検証には接続が必要です。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TwoInertiaVerifyPage</name>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="512" />
        <source>Verify with the profile</source>
        <translation>プロファイルで検証</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="513" />
        <source>The same profile as before the change, now with the filter: the measured load error y_L − y* against the prediction with and without the filter (ideal motor tracking), and the load − motor angle against the model's prediction from the measured motor motion (5.6).</source>
        <translation>変更前と同じプロファイルをフィルタありで実行します: 測定した負荷側誤差 y_L − y* をフィルタあり・なしの予測 (モータは理想追従) と比較し、負荷 − モータの角度を測定したモータの動きからモデルで予測した値 (5.6) と比較します。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="519" />
        <source>Time from the start of the move</source>
        <translation>移動開始からの時間</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="519" />
        <source>Load error y_L − y*</source>
        <translation>負荷側誤差 y_L − y*</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="572" />
        <source>predicted without the filter</source>
        <translation>予測、フィルタなし</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="574" />
        <source>predicted with the filter</source>
        <translation>予測、フィルタあり</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="576" />
        <source>measured before the change</source>
        <translation>測定、変更前</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="578" />
        <source>measured with the filter</source>
        <translation>測定、フィルタあり</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="602" />
        <source>The trace lacks t_s, position_cmd_rad, motor_pos_rad, motor_vel_rad_s or table_pos_rad (a rotary axis with a load encoder is needed).</source>
        <translation>トレースに t_s、position_cmd_rad、motor_pos_rad、motor_vel_rad_s または table_pos_rad がありません (負荷側エンコーダのある回転軸が必要です)。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="621" />
        <source>Maximum load error y_L − y* of the profile: measured with the filter %1°; predicted (ideal motor tracking) %2° without and %3° with the filter.</source>
        <translation>プロファイルでの負荷側誤差 y_L − y* の最大値: 測定値はフィルタあり %1°、予測値 (モータは理想追従) はフィルタなし %2°、フィルタあり %3° です。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="628" />
        <source>Measured before the change: %1° (ratio with/before %2).</source>
        <translation>変更前の測定値: %1° (フィルタあり/変更前の比 %2)。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="632" />
        <source>Measured with the filter / predicted without: %1 (the thesis reached 0.086, its criterion for a working filter is at most 0.2).</source>
        <translation>フィルタありの測定値/フィルタなしの予測値: %1 (論文の結果は 0.086、フィルタが有効と判断する基準は 0.2 以下)。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="635" />
        <source>Maximum load − motor angle: measured %1°, predicted from the measured motor motion %2°.</source>
        <translation>負荷 − モータの角度の最大値: 測定値 %1°、測定したモータの動きからの予測値 %2°。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizardPages.cpp" line="593" />
        <source>No verification run.</source>
        <translation>検証は実行されていません。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::TwoInertiaWizard</name>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="104" />
        <source>Two-inertia vibration suppression</source>
        <translation>2慣性系の振動抑制</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="109" />
        <source>Frequency response: a torque sine stream at the set amplitude is injected into the closed velocity loop (the axis oscillates about its position). Before and after applying the filter: one move with the profile's speed, acceleration and jerk (it does not return to the start).</source>
        <translation>周波数応答: 設定した振幅の正弦波トルクを閉じた速度ループに加振します (軸は現在位置の周りで振動します)。フィルタの適用前と適用後: プロファイルの速度・加速度・ジャークで 1 回移動します (開始位置には戻りません)。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="132" />
        <source>Profile before the change</source>
        <translation>変更前のプロファイル</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="139" />
        <source>Refused: the profile is given in motor revolutions and runs on rotary axes only; axis %1 is linear (its jog would be read in metres). Measure the load error with the NC's own test.</source>
        <translation>拒否: プロファイルはモータの回転数で与えられるため回転軸でのみ実行します。軸 %1 は直線軸です（ジョグがメートル単位として解釈されます）。負荷側の誤差は NC 自身のテストで測定してください。</translation>
    </message>
    <message>
        <location filename="../app/gui/TwoInertiaWizard.cpp" line="168" />
        <source>the suppression filter and gains</source>
        <translation>振動抑制フィルタとゲイン</translation>
    </message>
</context>
<context>
    <name>axistune::gui::VelocityLoopDesignPage</name>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="300" />
        <source>Velocity loop: proposal and prediction</source>
        <translation>速度ループ: 提案と予測</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="301" />
        <source>Predicted open loop L = C·P and closed loop T = L/(1 + L) with the proposed PI, the margins before and after, the position gain with its stability limit, and the predicted velocity step.</source>
        <translation>提案した PI での開ループ L = C·P と閉ループ T = L/(1 + L) の予測、変更前後の余裕、安定限界付きの位置ゲイン、速度ステップ応答の予測。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="310" />
        <source>Time from the step</source>
        <translation>ステップからの時間</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="310" />
        <source>Motor velocity / step</source>
        <translation>モータ速度 / ステップ</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="315" />
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="315" />
        <source>Before</source>
        <translation>適用前</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="315" />
        <source>Proposed</source>
        <translation>提案値</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="327" />
        <source>Also apply the recommended position gain K_p (the verification step tests the velocity loop only)</source>
        <translation>推奨の位置ゲイン K_p も適用する（検証のステップは速度ループだけを試験します）</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="423" />
        <source>Chapter 5 rule (corrected 5.13): K_P = k·√2·ω_l·J_m = %1·√2·2π·%2 Hz·%3 kg·m², K_I = k·ω_l²·J_m.</source>
        <translation>第 5 章の規則 (修正 5.13): K_P = k·√2·ω_l·J_m = %1·√2·2π·%2 Hz·%3 kg·m²、K_I = k·ω_l²·J_m。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="428" />
        <source>Margins on the measured plant: |C·P| = 1 and arg(C·P) = −180° + %1° at %2 Hz.</source>
        <translation>測定したプラントでの余裕: %2 Hz で |C·P| = 1 かつ arg(C·P) = −180° + %1°。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="381" />
        <source>No measured response.</source>
        <translation>測定した応答がありません。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="406" />
        <source>No proposal: %1</source>
        <translation>提案なし: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="437" />
        <source>Open loop L (proposed)</source>
        <translation>開ループ L (提案)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="438" />
        <source>Closed loop T (proposed)</source>
        <translation>閉ループ T (提案)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="439" />
        <source>Plant P (measured)</source>
        <translation>プラント P (測定)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="439" />
        <source>Plant P (model)</source>
        <translation>プラント P (モデル)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="443" />
        <source>crossover %1 Hz</source>
        <translation>交差周波数 %1 Hz</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="448" />
        <source>Measured before</source>
        <translation>変更前の測定</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="452" />
        <source>Predicted before</source>
        <translation>変更前の予測</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="456" />
        <source>Predicted with the proposal</source>
        <translation>提案での予測</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="464" />
        <source>K_P</source>
        <translation>K_P</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="464" />
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="465" />
        <source>N·m·s/rad</source>
        <translation>N·m·s/rad</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="466" />
        <source>K_I</source>
        <translation>K_I</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="466" />
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="467" />
        <source>N·m/rad</source>
        <translation>N·m/rad</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="468" />
        <source>Gain crossover</source>
        <translation>ゲイン交差周波数</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="469" />
        <source>Phase margin</source>
        <translation>位相余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="470" />
        <source>Gain margin</source>
        <translation>ゲイン余裕</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="471" />
        <source>Peak sensitivity</source>
        <translation>感度関数のピーク</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="472" />
        <source>Step overshoot (predicted)</source>
        <translation>ステップ応答のオーバーシュート (予測)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="474" />
        <source>Step overshoot (measured)</source>
        <translation>ステップ応答のオーバーシュート (測定)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="474" />
        <source>after applying</source>
        <translation>適用後</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="475" />
        <source>Position gain K_p</source>
        <translation>位置ゲイン K_p</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="477" />
        <source>Position gain stability limit</source>
        <translation>位置ゲインの安定限界</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="479" />
        <source>%1 1/s at %2 Hz</source>
        <translation>%1 1/s (%2 Hz)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="480" />
        <source>none on the model</source>
        <translation>モデル上ではなし</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="484" />
        <source>Position gain: recommended min(limit·10^(−%1/20), crossover·2π/5); %2.</source>
        <translation>位置ゲイン: 推奨値 min(限界·10^(−%1/20), 交差周波数·2π/5); %2。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="487" />
        <source>rigid model J_m with a delay of 1.5 velocity periods — fit a two-inertia model for the resonance</source>
        <translation>剛体モデル J_m と速度ループ周期 1.5 回分の遅れ — 共振を考慮するには 2慣性系モデルを同定してください</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="489" />
        <source>two-inertia model of session %1 with a delay of 1.5 velocity periods</source>
        <translation>セッション %1 の 2慣性系モデル (速度ループ周期 1.5 回分の遅れ付き)</translation>
    </message>
</context>
<context>
    <name>axistune::gui::VelocityLoopSavePage</name>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="40" />
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="41" />
        <source>The session holds the rule and its inputs, the proposed PI and position gain, the predicted loops with their margins, the steps before and after with the prediction, what was applied with its journal.</source>
        <translation>セッションには、規則とその入力、提案した PI と位置ゲイン、予測したループとその余裕、変更前後のステップ応答と予測、適用した内容とその履歴が保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="59" />
        <source>K_P = %1 N·m·s/rad, K_I = %2 N·m/rad; position gain %3 1/s.</source>
        <translation>K_P = %1 N·m·s/rad、K_I = %2 N·m/rad; 位置ゲイン %3 1/s。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="64" />
        <source>Not connected: nothing was applied.</source>
        <translation>未接続: 何も適用されていません。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="66" />
        <source>Not applied: the proposal is kept in the session.</source>
        <translation>未適用: 提案はセッションに保存されます。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="67" />
        <source>Saved as session %1.</source>
        <translation>セッション %1 として保存しました。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="68" />
        <source>The session was not saved (no store open).</source>
        <translation>セッションは保存されませんでした (データベースが開かれていません)。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::VelocityLoopSourcePage</name>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="66" />
        <source>Velocity loop: rule and data</source>
        <translation>速度ループ: 規則とデータ</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="67" />
        <source>The velocity PI from the fitted motor-side inertia (chapter 5 rule) or from the margins on a measured response; the position gain follows with its stability limit.</source>
        <translation>速度 PI を、同定したモータ側イナーシャ (第 5 章の規則) または測定した応答の余裕から決めます。位置ゲインは安定限界とともに決まります。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="73" />
        <source>Axis:</source>
        <translation>軸:</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="84" />
        <source>From the fitted inertia: K_P = k·√2·ω_l·J_m, K_I = k·ω_l²·J_m</source>
        <translation>同定したイナーシャから: K_P = k·√2·ω_l·J_m、K_I = k·ω_l²·J_m</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="86" />
        <source>From margins on a measured response (crossover and phase margin)</source>
        <translation>測定した応答の余裕から (交差周波数と位相余裕)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="102" />
        <source>Fitted model from:</source>
        <translation>同定モデルの出所:</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="103" />
        <source>Motor-side inertia J_m:</source>
        <translation>モータ側イナーシャ J_m:</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="104" />
        <source>Bandwidth ω_l/2π (for k = 1):</source>
        <translation>帯域 ω_l/2π (k = 1 のとき):</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="105" />
        <source>Gain factor k:</source>
        <translation>ゲイン係数 k:</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="113" />
        <source>Measure on the machine (torque injection, multi-sweep)</source>
        <translation>機械で測定 (トルク注入、複数回掃引)</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="115" />
        <source>From a saved session</source>
        <translation>保存済みセッションから</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="128" />
        <source>Crossover frequency:</source>
        <translation>交差周波数:</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="129" />
        <source>Phase margin:</source>
        <translation>位相余裕:</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="134" />
        <source> rad/s</source>
        <translation> rad/s</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="136" />
        <source>Velocity step before and after (motor):</source>
        <translation>変更前後の速度ステップ (モータ):</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="161" />
        <source>Axis %1 is a position loop the NC closes with a PID (%2): there is no drive velocity loop to tune. Next measures its open loop and proposes P, I, D, FF1, FF2 and a notch for it; the choices below do not apply.</source>
        <translation>軸 %1 は NC が PID で閉じる位置ループです (%2)。調整するサーボアンプの速度ループはありません。「次へ」で開ループを測定し、P、I、D、FF1、FF2 とノッチを提案します。下の選択は使いません。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="182" />
        <source>entered below</source>
        <translation>以下に入力</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="187" />
        <source>Session %1: %2, %3 axis %4, %5</source>
        <translation>セッション %1: %2、%3 軸 %4、%5</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="207" />
        <source>Before and after applying, a velocity step of the set size is run on the drive.</source>
        <translation>適用の前後に、設定した大きさの速度ステップをサーボアンプで実行します。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="208" />
        <source>Not connected: the proposal and prediction only; the steps, apply and verify need a connection.</source>
        <translation>未接続: 提案と予測のみ。ステップ応答、適用、検証には接続が必要です。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="231" />
        <source>Session %1: fitted J_m %2 kg·m², J_L %3 kg·m², K %4 N·m/rad; the prediction uses this two-inertia model.</source>
        <translation>セッション %1: 同定値 J_m %2 kg·m²、J_L %3 kg·m²、K %4 N·m/rad; 予測にはこの 2慣性系モデルを使います。</translation>
    </message>
</context>
<context>
    <name>axistune::gui::VelocityLoopVerifyPage</name>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="529" />
        <source>Velocity loop: verification</source>
        <translation>速度ループ: 検証</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="530" />
        <source>The velocity step measured before and after applying, with the prediction.</source>
        <translation>適用前後に測定した速度ステップ応答と予測。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="534" />
        <source>Time from the step</source>
        <translation>ステップからの時間</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="534" />
        <source>Motor velocity / step</source>
        <translation>モータ速度 / ステップ</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="552" />
        <source>Measured before</source>
        <translation>変更前の測定</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="556" />
        <source>Measured after</source>
        <translation>適用後の測定</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="560" />
        <source>Predicted after</source>
        <translation>適用後の予測</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="563" />
        <source>Overshoot: before %1 (measured), after %2 (measured), %3 predicted.</source>
        <translation>オーバーシュート: 変更前 %1 (測定)、変更後 %2 (測定)、予測 %3。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizardPages.cpp" line="565" />
        <source>No step after applying: %1</source>
        <translation>適用後のステップ応答なし: %1</translation>
    </message>
</context>
<context>
    <name>axistune::gui::VelocityLoopWizard</name>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="74" />
        <source>Velocity and position loop</source>
        <translation>速度ループと位置ループ</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="79" />
        <source>A velocity step of the set size (motor side) in the velocity loop, before and after applying; with a measured response first a torque sine stream in the closed velocity loop.</source>
        <translation>適用の前後に、速度ループで設定した大きさ (モータ側) の速度ステップ。測定した応答を使う場合は、最初に速度閉ループで正弦波トルクを注入します。</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="132" />
        <source>the velocity-loop gains</source>
        <translation>速度ループゲイン</translation>
    </message>
    <message>
        <location filename="../app/gui/VelocityLoopWizard.cpp" line="141" />
        <source>The step after applying failed: %1</source>
        <translation>適用後のステップ応答が失敗しました: %1</translation>
    </message>
</context>
<context>
    <name>axistune::widgets::BodePlot</name>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="167" />
        <location filename="../widgets/BodePlot.cpp" line="452" />
        <source>Magnitude</source>
        <translation>ゲイン</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="167" />
        <location filename="../widgets/BodePlot.cpp" line="452" />
        <source>dB</source>
        <translation>dB</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="168" />
        <source>Phase</source>
        <translation>位相</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="168" />
        <source>deg</source>
        <translation>deg</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="169" />
        <source>Coherence</source>
        <translation>コヒーレンス</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="169" />
        <source>0–1</source>
        <translation>0–1</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="354" />
        <source>above the observation Nyquist: valid only by multi-sweep or multisine</source>
        <translation>観測ナイキスト周波数以上: 複数回掃引またはマルチサインでのみ有効</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="355" />
        <source>not measurable</source>
        <translation>測定不可</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="498" />
        <source>Frequency</source>
        <translation>周波数</translation>
    </message>
    <message>
        <location filename="../widgets/BodePlot.cpp" line="498" />
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
</context>
<context>
    <name>axistune::widgets::CurvePlot</name>
    <message>
        <location filename="../widgets/CurvePlot.cpp" line="26" />
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <location filename="../widgets/CurvePlot.cpp" line="26" />
        <source>y</source>
        <translation>y</translation>
    </message>
</context>
<context>
    <name>axistune::widgets::PolarPlot</name>
    <message>
        <location filename="../widgets/PolarPlot.cpp" line="159" />
        <source>Scale: %1 µm/div, magnification ×%2, radius %3 mm</source>
        <translation>スケール: %1 µm/目盛, 倍率 ×%2, 半径 %3 mm</translation>
    </message>
</context>
<context>
    <name>axistune::widgets::TimeTracePlot</name>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="128" />
        <source>Velocity</source>
        <translation>速度</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="130" />
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="132" />
        <source>Torque</source>
        <translation>トルク</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="134" />
        <source>Force</source>
        <translation>力</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="136" />
        <source>Current</source>
        <translation>電流</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="138" />
        <source>Voltage</source>
        <translation>電圧</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="140" />
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="142" />
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="143" />
        <source>Value</source>
        <translation>値</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="353" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="353" />
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="582" />
        <source>t1 = %1 s   t2 = %2 s   Δt = %3 s</source>
        <translation>t1 = %1 s   t2 = %2 s   Δt = %3 s</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="585" />
        <source>   1/Δt = %1 Hz</source>
        <translation>   1/Δt = %1 Hz</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="592" />
        <source>%1: %2%5 | %3%5 | Δ %4%5</source>
        <translation>%1: %2%5 | %3%5 | Δ %4%5</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="673" />
        <source>%1: the series have different time bases; export them one by one</source>
        <translation>%1: 系列ごとに時間軸が異なります。1 つずつ書き出ししてください</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="679" />
        <source>%1: nothing to export: the plot is empty</source>
        <translation>%1: 書き出しするものがありません (プロットが空です)</translation>
    </message>
    <message>
        <location filename="../widgets/TimeTracePlot.cpp" line="706" />
        <source>%1: cannot write the file (%2)</source>
        <translation>%1: ファイルを書き込めません (%2)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="28" />
        <source>Commissioning and tuning of NC feed axes</source>
        <translation>NC工作機械送り軸の立上げと調整</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="32" />
        <source>Simulated machine preset (vmc, dd-table, two-inertia, long-axis).</source>
        <translation>シミュレーション機のプリセット (vmc, dd-table, two-inertia, long-axis)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="34" />
        <source>Connect to this drive: sim:PRESET or modbus://HOST:PORT.</source>
        <translation>このサーボアンプに接続: sim:PRESET または modbus://HOST:PORT。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="36" />
        <source>Start without a connection.</source>
        <translation>接続せずに起動します。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="37" />
        <source>Language: en or ja (overrides the settings).</source>
        <translation>言語: en または ja (設定より優先)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="38" />
        <source>Store file (default: the one of the settings).</source>
        <translation>データベースファイル (既定: 設定のファイル)。</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="39" />
        <source>Save a screenshot of the main window and quit.</source>
        <translation>メインウィンドウのスクリーンショットを保存して終了します。</translation>
    </message>
</context>
</TS>