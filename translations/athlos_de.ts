<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE" sourcelanguage="en">
<context>
    <name>Tools</name>
    <message>
        <source>Calibrate LPS…</source>
        <translation>LPS kalibrieren…</translation>
    </message>
    <message>
        <source>Positioning</source>
        <translation>Positionierung</translation>
    </message>
    <message>
        <source>Orientation angles…</source>
        <translation>Orientierungswinkel…</translation>
    </message>
    <message>
        <source>Inertial</source>
        <translation>Inertial</translation>
    </message>
    <message>
        <source>Filter positions…</source>
        <translation>Positionen filtern…</translation>
    </message>
    <message>
        <source>Action timeline…</source>
        <translation>Aktionszeitleiste…</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>Import Wizard…</source>
        <translation>Import-Assistent…</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Joint angles…</source>
        <translation>Gelenkwinkel…</translation>
    </message>
    <message>
        <source>Team playback…</source>
        <translation>Mannschaftswiedergabe …</translation>
    </message>
    <message>
        <source>Video…</source>
        <translation>Video…</translation>
    </message>
    <message>
        <source>Export report…</source>
        <translation>Bericht exportieren…</translation>
    </message>
    <message>
        <source>Train classifier…</source>
        <translation>Klassifikator trainieren…</translation>
    </message>
    <message>
        <source>Processing</source>
        <translation>Verarbeitung</translation>
    </message>
    <message>
        <source>Cycle-normalised curves…</source>
        <translation>Zyklusnormierte Kurven…</translation>
    </message>
    <message>
        <source>Stick figure (centre of mass)…</source>
        <translation>Strichfigur (Körperschwerpunkt)…</translation>
    </message>
    <message>
        <source>Functional calibration…</source>
        <translation>Funktionelle Kalibrierung…</translation>
    </message>
    <message>
        <source>Stride and cycle table…</source>
        <translation>Schritt- und Zyklustabelle…</translation>
    </message>
    <message>
        <source>Export gait report…</source>
        <translation>Ganganalyse-Bericht exportieren…</translation>
    </message>
</context>
<context>
    <name>athlos::activity::ClassifyActionsProcessor</name>
    <message>
        <source>Classify actions (trained model)</source>
        <translation>Aktionen klassifizieren (trainiertes Modell)</translation>
    </message>
    <message>
        <source>Name of the trained model in the project (athlos train --model).</source>
        <translation>Name des trainierten Modells im Projekt (athlos train --model).</translation>
    </message>
    <message>
        <source>Windows on each side whose class probabilities are averaged with a window&apos;s own before deciding (0: none); activities last longer than a window.</source>
        <translation>Fenster auf jeder Seite, deren Klassenwahrscheinlichkeiten vor der Entscheidung mit denen des Fensters gemittelt werden (0: keine); Aktivitäten dauern länger als ein Fenster.</translation>
    </message>
    <message>
        <source>IMU stream with the columns the model was trained on (acc_x..z, gyr_x..z, ...).</source>
        <translation>IMU-Datenstrom mit den Spalten, auf denen das Modell trainiert wurde (acc_x..z, gyr_x..z, ...).</translation>
    </message>
    <message>
        <source>Activities as predicted annotations with confidence.</source>
        <translation>Aktivitäten als vorhergesagte Annotationen mit Konfidenz.</translation>
    </message>
    <message>
        <source>Classifies sliding windows of an IMU stream with a model trained in this project (athlos train) and writes the activities as predicted annotations with confidence: consecutive windows of one class merge into one interval and the intervals cover the whole stream. A model trained on detected events (--segmentation events:impact or events:tackle) runs its detector and writes one annotation per event that is not classified as null. A model with interaction features (athlos train --interaction) also reads the other athletes&apos; IMU and positions streams of the input&apos;s recording (athlete and team attributes, as simulate-rugby writes them).</source>
        <translation>Klassifiziert gleitende Fenster eines IMU-Streams mit einem in diesem Projekt trainierten Modell (athlos train) und schreibt die Aktivitäten als vorhergesagte Annotationen mit Konfidenz: aufeinanderfolgende Fenster einer Klasse werden zu einem Intervall zusammengefasst, und die Intervalle decken den ganzen Stream ab. Ein auf erkannten Ereignissen trainiertes Modell (--segmentation events:impact oder events:tackle) führt seinen Detektor aus und schreibt je Ereignis, das nicht als null klassifiziert wird, eine Annotation. Ein Modell mit Interaktionsmerkmalen (athlos train --interaction) liest zusätzlich die IMU- und Positions-Streams der anderen Athleten in der Aufnahme des Eingangs (Attribute athlete und team, wie simulate-rugby sie schreibt).</translation>
    </message>
</context>
<context>
    <name>athlos::activity::DetectScrumsProcessor</name>
    <message>
        <source>Detect scrums (top-6 torso pitch)</source>
        <translation>Gedränge erkennen (Top-6-Rumpfneigung)</translation>
    </message>
    <message>
        <source>Finds scrums in a team session: the torso pitch of every player from the upper-back accelerometer (gravity direction against the upright standing posture), sorted at each instant; where the mean of the six largest stays above the threshold for the minimum duration, with those players close together, a scrum annotation is written. Uses every IMU stream of the input&apos;s recording.</source>
        <translation>Findet Gedränge in einer Mannschaftseinheit: die Rumpfneigung jedes Spielers aus dem Beschleunigungsmesser am oberen Rücken (Schwerkraftrichtung gegenüber der aufrechten Haltung), zu jedem Zeitpunkt sortiert; wo der Mittelwert der sechs größten für die Mindestdauer über der Schwelle bleibt und diese Spieler nahe beieinander sind, wird eine Annotation scrum geschrieben. Verwendet jeden IMU-Datenstrom der Aufnahme der Eingabe.</translation>
    </message>
    <message>
        <source>Largest torso pitches averaged at each instant (seed 000 §5.1.2: the six players of a sevens scrum).</source>
        <translation>Größte Rumpfneigungen, die zu jedem Zeitpunkt gemittelt werden (Quelle 000 §5.1.2: die sechs Spieler eines Siebener-Gedränges).</translation>
    </message>
    <message>
        <source>Scrum when the mean of the largest torso pitches exceeds this (0.96 rad = 55°, between running &lt; 25° and binding 60–90°; the thesis fits it by grid search so that no scrum is missed, seed 000 §5.1.2, Fig. 5.6).</source>
        <translation>Gedränge, wenn der Mittelwert der größten Rumpfneigungen diesen Wert übersteigt (0,96 rad = 55°, zwischen Laufen &lt; 25° und Binden 60–90°; die Arbeit passt ihn per Rastersuche so an, dass kein Gedränge verpasst wird, Quelle 000 §5.1.2, Abb. 5.6).</translation>
    </message>
    <message>
        <source>Shorter episodes are not scrums (a scrum lasts several seconds; tackles and players bending for the ball are brief).</source>
        <translation>Kürzere Episoden sind keine Gedränge (ein Gedränge dauert mehrere Sekunden; Tackles und Spieler, die sich nach dem Ball bücken, sind kurz).</translation>
    </message>
    <message>
        <source>Largest distance of those players from their centroid (bound players are within ~2 m of each other); 0 or no position streams: not checked.</source>
        <translation>Größter Abstand dieser Spieler von ihrem Schwerpunkt (gebundene Spieler sind höchstens ~2 m voneinander entfernt); 0 oder keine Positionsdatenströme: nicht geprüft.</translation>
    </message>
    <message>
        <source>Low-pass of the accelerometer that leaves the direction of gravity (torso pitch).</source>
        <translation>Tiefpass des Beschleunigungsmessers, der die Schwerkraftrichtung übrig lässt (Rumpfneigung).</translation>
    </message>
    <message>
        <source>Start of the standing period whose gravity direction is each player&apos;s upright reference (sensor alignment correction, seed 000 Fig. 5.5).</source>
        <translation>Beginn der Stehphase, deren Schwerkraftrichtung die aufrechte Referenz jedes Spielers ist (Korrektur der Sensorausrichtung, Quelle 000 Abb. 5.5).</translation>
    </message>
    <message>
        <source>Length of the standing period; 0: the sensor axis up_axis is upright.</source>
        <translation>Länge der Stehphase; 0: die Sensorachse up_axis ist aufrecht.</translation>
    </message>
    <message>
        <source>The sensor axis that points up when the player stands (reference_duration 0).</source>
        <translation>Die Sensorachse, die nach oben zeigt, wenn der Spieler steht (reference_duration 0).</translation>
    </message>
    <message>
        <source>One upper-back IMU stream of the session; all IMU streams of its recording are used.</source>
        <translation>Ein IMU-Datenstrom vom oberen Rücken der Einheit; alle IMU-Datenströme seiner Aufnahme werden verwendet.</translation>
    </message>
    <message>
        <source>Scrums as predicted annotations.</source>
        <translation>Gedränge als vorhergesagte Annotationen.</translation>
    </message>
</context>
<context>
    <name>athlos::activity::SimulateRugbyProcessor</name>
    <message>
        <source>Simulate rugby sevens match</source>
        <translation>Siebener-Rugbyspiel simulieren</translation>
    </message>
    <message>
        <source>Simulates a rugby sevens match of 2 × 7 players: positions (~80 Hz) and an upper-back IMU (200 Hz) per player, with running play, tackles (two players collide and go to ground), contacts and falls that are not tackles, and scrums (the front rows bind with the torso pitched 60–90° forward). The true scrums and tackles are written as annotations.</source>
        <translation>Simuliert ein Siebener-Rugbyspiel mit 2 × 7 Spielern: Positionen (~80 Hz) und eine IMU am oberen Rücken (200 Hz) je Spieler, mit offenem Spiel, Tackles (zwei Spieler prallen zusammen und gehen zu Boden), Kontakten und Stürzen, die keine Tackles sind, und Gedrängen (die erste Reihe bindet mit 60–90° nach vorn geneigtem Rumpf). Die wahren Gedränge und Tackles werden als Annotationen geschrieben.</translation>
    </message>
    <message>
        <source>Random seed (deterministic).</source>
        <translation>Zufallsstartwert (deterministisch).</translation>
    </message>
    <message>
        <source>Length of the match.</source>
        <translation>Länge des Spiels.</translation>
    </message>
    <message>
        <source>Number of scrums.</source>
        <translation>Anzahl der Gedränge.</translation>
    </message>
    <message>
        <source>Number of tackles.</source>
        <translation>Anzahl der Tackles.</translation>
    </message>
    <message>
        <source>Collisions of two opponents who stay on their feet (not tackles, not annotated).</source>
        <translation>Zusammenstöße zweier Gegner, die auf den Beinen bleiben (keine Tackles, nicht annotiert).</translation>
    </message>
    <message>
        <source>Players going to ground alone, away from opponents (not tackles, not annotated).</source>
        <translation>Spieler, die allein, abseits von Gegnern, zu Boden gehen (keine Tackles, nicht annotiert).</translation>
    </message>
    <message>
        <source>Players of each team bound in a scrum (3 in sevens: the front row, seed 000 §5.1.1).</source>
        <translation>Spieler je Mannschaft, die in einem Gedränge gebunden sind (3 im Siebener: die erste Reihe, Quelle 000 §5.1.1).</translation>
    </message>
    <message>
        <source>Sampling rate of the positions (the LPS&apos;s ~80 Hz, seed 000 §5.1.2).</source>
        <translation>Abtastrate der Positionen (die ~80 Hz des LPS, Quelle 000 §5.1.2).</translation>
    </message>
    <message>
        <source>Sampling rate of the IMU (200 Hz, seed 000 §5.1.2).</source>
        <translation>Abtastrate der IMU (200 Hz, Quelle 000 §5.1.2).</translation>
    </message>
    <message>
        <source>Upper-back IMU of player %1: acc_x..z (m/s²), gyr_x..z (rad/s).</source>
        <translation>IMU am oberen Rücken von Spieler %1: acc_x..z (m/s²), gyr_x..z (rad/s).</translation>
    </message>
    <message>
        <source>Positions t, x, y (m) of player %1.</source>
        <translation>Positionen t, x, y (m) von Spieler %1.</translation>
    </message>
    <message>
        <source>The true scrums and tackles as annotations.</source>
        <translation>Die wahren Gedränge und Tackles als Annotationen.</translation>
    </message>
</context>
<context>
    <name>athlos::body::BodyComProcessor</name>
    <message>
        <source>Centre of mass (body model)</source>
        <translation>Körperschwerpunkt (Körpermodell)</translation>
    </message>
    <message>
        <source>Joint centres and centre of mass relative to the lumbar joint centre (ENU axes) through the kinematic chain p_hip = R_pelvis v_hip, p_knee = p_hip + R_thigh v_knee, … (Fasel 2017 ch. 7) with the body model&apos;s anthropometric table; segment orientations = sensor orientation × mount. Sensor-to-joint vectors from a table or drift-reduction&apos;s attributes replace the table&apos;s thigh/shank/pelvis lengths. Head and arms without sensors ride on the thorax (arms in a fixed posture). Also the fore-aft CoM against the feet and, with an antenna in the model, the absolute CoM = antenna + chain offset and its speed (ch. 8).</source>
        <translation>Gelenkzentren und Körperschwerpunkt relativ zum Lumbalgelenkzentrum (ENU-Achsen) über die kinematische Kette p_hip = R_pelvis v_hip, p_knee = p_hip + R_thigh v_knee, … (Fasel 2017 Kap. 7) mit der anthropometrischen Tabelle des Körpermodells; Segmentorientierung = Sensororientierung × Montage. Sensor-Gelenk-Vektoren aus einer Tabelle oder den Attributen von drift-reduction ersetzen die Oberschenkel-, Unterschenkel- und Beckenlängen der Tabelle. Kopf und Arme ohne Sensor sitzen auf dem Thorax (Arme in fester Haltung). Außerdem der Schwerpunkt in Längsrichtung gegenüber den Füßen und, mit einer Antenne im Modell, der absolute Schwerpunkt = Antenne + Kettenversatz und seine Geschwindigkeit (Kap. 8).</translation>
    </message>
    <message>
        <source>Joint vectors: the joint-vectors table, drift-reduction&apos;s sensor_to_joint attributes of the sensor streams, or the anthropometric table only (auto: the first present).</source>
        <translation>Gelenkvektoren: die Gelenkvektor-Tabelle, die sensor_to_joint-Attribute von drift-reduction an den Sensordatenströmen oder nur die anthropometrische Tabelle (auto: das erste Vorhandene).</translation>
    </message>
    <message>
        <source>Fixed arm posture on the thorax: shoulder flexion (a skier holding the poles; an assumption, arms carry no sensor).</source>
        <translation>Feste Armhaltung am Thorax: Schulterflexion (ein Skifahrer hält die Stöcke; eine Annahme, die Arme tragen keinen Sensor).</translation>
    </message>
    <message>
        <source>Fixed arm posture: elbow flexion.</source>
        <translation>Feste Armhaltung: Ellbogenflexion.</translation>
    </message>
    <message>
        <source>none: the orientations share one heading (drift-reduction outputs, 9D); align-start: 6D orientations with unrelated headings, each segment turned about the vertical so its anterior axis matches the pelvis&apos; over the first 2 s (standing upright).</source>
        <translation>none: die Orientierungen teilen eine Richtung (Ausgaben von drift-reduction, 9D); align-start: 6D-Orientierungen mit voneinander unabhängigen Richtungen, jedes Segment wird um die Vertikale gedreht, bis seine anteriore Achse über die ersten 2 s (aufrechtes Stehen) der des Beckens entspricht.</translation>
    </message>
    <message>
        <source>Absolute CoM speed: central difference over this span (antenna noise).</source>
        <translation>Geschwindigkeit des absoluten Schwerpunkts: zentrale Differenz über diese Spanne (Antennenrauschen).</translation>
    </message>
    <message>
        <source>Body model (body-model).</source>
        <translation>Körpermodell (body-model).</translation>
    </message>
    <message>
        <source>Sensor mounts (segment-calibration): pelvis, thorax, right leg (or full segment names); absent = sensors aligned with their segments.</source>
        <translation>Sensormontagen (segment-calibration): Becken, Thorax, rechtes Bein (oder vollständige Segmentnamen); fehlt sie, sind die Sensoren an ihren Segmenten ausgerichtet.</translation>
    </message>
    <message>
        <source>Mounts of the left leg (thigh, shank, foot).</source>
        <translation>Montagen des linken Beins (Oberschenkel, Unterschenkel, Fuß).</translation>
    </message>
    <message>
        <source>Sensor-to-joint vectors (joint, rp_x..z, rd_x..z in the sensors&apos; frames).</source>
        <translation>Sensor-Gelenk-Vektoren (joint, rp_x..z, rd_x..z in den Koordinaten der Sensoren).</translation>
    </message>
    <message>
        <source>com_x, com_y, com_z (m, relative to the lumbar joint centre, ENU axes), fore_aft and above_ankles (m, against the mid-ankle point along the feet&apos;s heading / vertical).</source>
        <translation>com_x, com_y, com_z (m, relativ zum Lumbalgelenkzentrum, ENU-Achsen), fore_aft und above_ankles (m, gegenüber dem Punkt zwischen den Knöcheln entlang der Fußrichtung / vertikal).</translation>
    </message>
    <message>
        <source>&lt;joint&gt;_x..z of the 15 joints (m, relative to the lumbar joint centre, ENU axes).</source>
        <translation>&lt;joint&gt;_x..z der 15 Gelenke (m, relativ zum Lumbalgelenkzentrum, ENU-Achsen).</translation>
    </message>
    <message>
        <source>Only with an antenna: the absolute CoM x, y, z (m, the antenna stream&apos;s frame), vx, vy, vz and speed (m/s) on the antenna&apos;s time axis (a trajectory: drawn on the venue).</source>
        <translation>Nur mit Antenne: absoluter Schwerpunkt x, y, z (m, im Bezugssystem des Antennendatenstroms), vx, vy, vz und Geschwindigkeit (m/s) auf der Zeitachse der Antenne (eine Trajektorie: wird auf dem Gelände gezeichnet).</translation>
    </message>
</context>
<context>
    <name>athlos::body::BodyModelProcessor</name>
    <message>
        <source>Body model</source>
        <translation>Körpermodell</translation>
    </message>
    <message>
        <source>The athlete&apos;s body model (Fasel 2017 ch. 7): 15 segments (pelvis, thorax, head, upper arms, forearms, hands, thighs, shanks, feet) with the anthropometric table scaled to height and mass (Dumas et al. 2007 Table 2 or de Leva 1996 Table 4), which orientation stream (sensor) sits on which segment, equipment masses and an optional GNSS/LPS antenna. A table of kind body-model, read by body-com.</source>
        <translation>Das Körpermodell des Athleten (Fasel 2017 Kap. 7): 15 Segmente (Becken, Thorax, Kopf, Oberarme, Unterarme, Hände, Oberschenkel, Unterschenkel, Füße) mit der auf Größe und Masse skalierten anthropometrischen Tabelle (Dumas et al. 2007 Tabelle 2 oder de Leva 1996 Tabelle 4), welcher Orientierungsdatenstrom (Sensor) auf welchem Segment sitzt, Ausrüstungsmassen und eine optionale GNSS/LPS-Antenne. Eine Tabelle der Art body-model, gelesen von body-com.</translation>
    </message>
    <message>
        <source>Athlete&apos;s height (scales the segment lengths).</source>
        <translation>Körpergröße des Athleten (skaliert die Segmentlängen).</translation>
    </message>
    <message>
        <source>Athlete&apos;s body mass without equipment.</source>
        <translation>Körpermasse des Athleten ohne Ausrüstung.</translation>
    </message>
    <message>
        <source>Selects the table&apos;s male or female column.</source>
        <translation>Wählt die männliche oder weibliche Spalte der Tabelle.</translation>
    </message>
    <message>
        <source>Anthropometric table: Dumas, Chèze &amp; Verriest 2007 (J Biomech 40:543, Table 2) or de Leva 1996 (J Biomech 29:1223, Table 4).</source>
        <translation>Anthropometrische Tabelle: Dumas, Chèze &amp; Verriest 2007 (J Biomech 40:543, Tabelle 2) oder de Leva 1996 (J Biomech 29:1223, Tabelle 4).</translation>
    </message>
    <message>
        <source>segment:rec/stream,… — the orientation stream of the sensor on each segment (e.g. the outputs of drift-reduction). Segments without one ride on their parent.</source>
        <translation>segment:rec/stream,… — der Orientierungsdatenstrom des Sensors auf jedem Segment (z. B. die Ausgaben von drift-reduction). Segmente ohne einen solchen sitzen auf ihrem Elternsegment.</translation>
    </message>
    <message>
        <source>segment:kg,… — equipment masses (boots, helmet, skis), added at the segment&apos;s CoM.</source>
        <translation>segment:kg,… — Ausrüstungsmassen (Schuhe, Helm, Ski), im Schwerpunkt des Segments hinzugefügt.</translation>
    </message>
    <message>
        <source>segment:rec/stream — a GNSS (local x, y, z) or LPS position stream of an antenna on that segment (helmet: head; back: thorax), for the absolute CoM (Fasel 2017 ch. 8).</source>
        <translation>segment:rec/stream — ein GNSS- (lokal x, y, z) oder LPS-Positionsdatenstrom einer Antenne auf diesem Segment (Helm: Kopf; Rücken: Thorax), für den absoluten Schwerpunkt (Fasel 2017 Kap. 8).</translation>
    </message>
    <message>
        <source>x,y,z (m): the antenna in the segment&apos;s coordinates from its proximal joint (default: 3 cm above the head vertex, or the segment&apos;s distal end).</source>
        <translation>x,y,z (m): die Antenne in den Koordinaten des Segments ab seinem proximalen Gelenk (Vorgabe: 3 cm über dem Scheitel bzw. das distale Ende des Segments).</translation>
    </message>
    <message>
        <source>One row per segment: segment, parent, joints, sensor, position, equipment, mass, length.</source>
        <translation>Eine Zeile je Segment: segment, parent, joints, sensor, position, equipment, mass, length.</translation>
    </message>
</context>
<context>
    <name>athlos::events</name>
    <message>
        <source>The walker&apos;s height (feature x4 of eq. 12.6); required, 0 = not given.</source>
        <translation>Körpergröße der gehenden Person (Merkmal x4 aus Gl. 12.6); erforderlich, 0 = nicht angegeben.</translation>
    </message>
    <message>
        <source>Sensor axis pointing forward along the ski.</source>
        <translation>Sensorachse, die entlang des Skis nach vorn zeigt.</translation>
    </message>
    <message>
        <source>Sensor axis pointing to the skier&apos;s left (medio-lateral); the ski inclination is integrated from this gyroscope axis.</source>
        <translation>Sensorachse, die zur linken Seite des Skifahrers zeigt (medio-lateral); die Skineigung wird aus dieser Gyroskopachse integriert.</translation>
    </message>
    <message>
        <source>Speed below which the ski is motionless (refined phases; Fasel 2017 ch. 4: 0.1 m/s).</source>
        <translation>Geschwindigkeit, unter der der Ski ruht (verfeinerte Phasen; Fasel 2017 Kap. 4: 0,1 m/s).</translation>
    </message>
    <message>
        <source>Shortest cycle; closer motionless phases are not separate cycles.</source>
        <translation>Kürzester Zyklus; näher beieinanderliegende Ruhephasen sind keine eigenen Zyklen.</translation>
    </message>
    <message>
        <source>Longest cycle; longer gaps between motionless phases are not cycles.</source>
        <translation>Längster Zyklus; längere Lücken zwischen Ruhephasen sind keine Zyklen.</translation>
    </message>
    <message>
        <source>Longest motionless phase that starts a cycle; longer ones are rests (used for the drift correction only).</source>
        <translation>Längste Ruhephase, die einen Zyklus beginnt; längere sind Pausen (nur für die Driftkorrektur verwendet).</translation>
    </message>
    <message>
        <source>Gyroscope norm below which the ski may be still (candidate thrust phases; Fasel 2017 ch. 3).</source>
        <translation>Gyroskopnorm, unter der der Ski ruhen kann (Kandidaten für Abstoßphasen; Fasel 2017 Kap. 3).</translation>
    </message>
    <message>
        <source>|‖a‖ − g| below which the ski may be still (candidate thrust phases).</source>
        <translation>|‖a‖ − g|, unter dem der Ski ruhen kann (Kandidaten für Abstoßphasen).</translation>
    </message>
    <message>
        <source>Shortest candidate thrust phase.</source>
        <translation>Kürzeste Kandidaten-Abstoßphase.</translation>
    </message>
    <message>
        <source>Inertial acceleration below which the ski is motionless (thrust start and end, Fasel 2017 Table 3.1).</source>
        <translation>Inertiale Beschleunigung, unter der der Ski ruht (Beginn und Ende des Abstoßes, Fasel 2017 Tabelle 3.1).</translation>
    </message>
    <message>
        <source>Pole: vibration maximum (second difference of the acceleration norm) of a pole plant.</source>
        <translation>Stock: Vibrationsmaximum (zweite Differenz der Beschleunigungsnorm) eines Stockeinsatzes.</translation>
    </message>
    <message>
        <source>Pole: vibration at the start of the plant shock, searched up to 100 ms before the maximum (Fasel 2017 ch. 3).</source>
        <translation>Stock: Vibration zu Beginn des Einsatzstoßes, gesucht bis 100 ms vor dem Maximum (Fasel 2017 Kap. 3).</translation>
    </message>
    <message>
        <source>The ski stands still for this long at the start of the recording (first inclination and gyroscope bias).</source>
        <translation>So lange steht der Ski zu Beginn der Aufnahme still (erste Neigung und Gyroskop-Bias).</translation>
    </message>
    <message>
        <source>Sensor axis along the medio-lateral direction (y when x points forward and z up); auto: the principal axis of the angular velocity, whatever the mounting.</source>
        <translation>Sensorachse in medio-lateraler Richtung (y, wenn x nach vorn und z nach oben zeigt); auto: die Hauptachse der Winkelgeschwindigkeit, unabhängig von der Befestigung.</translation>
    </message>
    <message>
        <source>Sign of the medio-lateral angular velocity during swing; auto: the sign of the longest sustained rotation.</source>
        <translation>Vorzeichen der medio-lateralen Winkelgeschwindigkeit im Schwung; auto: das Vorzeichen der längsten anhaltenden Drehung.</translation>
    </message>
    <message>
        <source>Minimum mid-swing angular velocity of a stride (walking peaks are 4–7 rad/s, Rampp et al. 2015).</source>
        <translation>Minimale Winkelgeschwindigkeit in der Schwungmitte eines Doppelschritts (beim Gehen 4–7 rad/s, Rampp et al. 2015).</translation>
    </message>
    <message>
        <source>Shortest stride; closer swing peaks count as one.</source>
        <translation>Kürzester Doppelschritt; näher beieinanderliegende Schwungspitzen zählen als eine.</translation>
    </message>
    <message>
        <source>Search window for toe-off before the swing peak.</source>
        <translation>Suchfenster für die Zehenablösung vor der Schwungspitze.</translation>
    </message>
    <message>
        <source>Search window for initial contact after the swing peak.</source>
        <translation>Suchfenster für den Initialkontakt nach der Schwungspitze.</translation>
    </message>
</context>
<context>
    <name>athlos::events::AlpineTurnsProcessor</name>
    <message>
        <source>Alpine turn switches</source>
        <translation>Schwungwechsel im alpinen Skilauf</translation>
    </message>
    <message>
        <source>Turn switches of alpine skiing from a trunk or sacrum IMU (Fasel 2017 ch. 2 and 11): the angular velocity about the trunk&apos;s longitudinal axis changes sign at each switch; positive is a left turn. Writes the turns (switch to switch) as predicted annotations &quot;turn left&quot; / &quot;turn right&quot; and a per-turn table.</source>
        <translation>Schwungwechsel im alpinen Skilauf aus einer IMU an Rumpf oder Kreuzbein (Fasel 2017 Kap. 2 und 11): die Winkelgeschwindigkeit um die Längsachse des Rumpfes wechselt bei jedem Wechsel das Vorzeichen; positiv ist ein Linksschwung. Schreibt die Schwünge (von Wechsel zu Wechsel) als vorhergesagte Annotationen „turn left“ / „turn right“ und eine Tabelle je Schwung.</translation>
    </message>
    <message>
        <source>Sensor axis along the trunk pointing up; auto: the axis nearest the mean acceleration.</source>
        <translation>Sensorachse entlang des Rumpfes nach oben; auto: die Achse, die der mittleren Beschleunigung am nächsten liegt.</translation>
    </message>
    <message>
        <source>Moving-average window (applied twice) on the yaw rate.</source>
        <translation>Fenster des gleitenden Mittelwerts (zweimal angewandt) auf die Gierrate.</translation>
    </message>
    <message>
        <source>Yaw rate a turn must exceed; smaller sign changes are not switches.</source>
        <translation>Gierrate, die ein Schwung überschreiten muss; kleinere Vorzeichenwechsel sind keine Wechsel.</translation>
    </message>
    <message>
        <source>Shortest turn.</source>
        <translation>Kürzester Schwung.</translation>
    </message>
    <message>
        <source>Longest turn; longer intervals (straight running, stops) are not turns.</source>
        <translation>Längster Schwung; längere Intervalle (Schussfahrt, Halte) sind keine Schwünge.</translation>
    </message>
    <message>
        <source>Sacrum or trunk IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</source>
        <translation>IMU an Kreuzbein oder Rumpf: acc_x..z (m/s^2), gyr_x..z (rad/s).</translation>
    </message>
    <message>
        <source>Per turn: start, end, duration (s), side (left/right), peak_rate (rad/s).</source>
        <translation>Je Schwung: start, end, duration (s), side (left/right), peak_rate (rad/s).</translation>
    </message>
    <message>
        <source>Turns as predicted annotations &quot;turn left&quot; / &quot;turn right&quot;.</source>
        <translation>Schwünge als vorhergesagte Annotationen „turn left“ / „turn right“.</translation>
    </message>
</context>
<context>
    <name>athlos::events::GaitEventsProcessor</name>
    <message>
        <source>Gait events (foot IMU)</source>
        <translation>Gangereignisse (Fuß-IMU)</translation>
    </message>
    <message>
        <source>Initial contact, toe-off and mid-stance from the medio-lateral gyroscope of a foot-mounted IMU (negative peaks of the swing-positive signal after and before each mid-swing peak; minimum of the gyroscope norm in stance). Writes the strides (IC to next IC) as predicted annotations with a confidence, and a table of the events.</source>
        <translation>Initialkontakt, Zehenablösung und Mittelstand aus dem medio-lateralen Gyroskop einer am Fuß getragenen IMU (negative Spitzen des in der Schwungphase positiven Signals nach und vor jeder Schwungspitze; Minimum der Gyroskopnorm im Stand). Schreibt die Doppelschritte (IC bis zum nächsten IC) als vorhergesagte Annotationen mit Konfidenz und eine Tabelle der Ereignisse.</translation>
    </message>
    <message>
        <source>Longest stride; longer intervals between contacts are gaps.</source>
        <translation>Längster Doppelschritt; längere Intervalle zwischen Kontakten sind Lücken.</translation>
    </message>
    <message>
        <source>Annotation label of the strides; empty: &quot;stride left&quot; / &quot;stride right&quot; from the stream name.</source>
        <translation>Annotationsbezeichnung der Doppelschritte; leer: „stride left“ / „stride right“ aus dem Namen des Datenstroms.</translation>
    </message>
    <message>
        <source>Foot-mounted IMU: gyr_x..z (rad/s) in the sensor frame.</source>
        <translation>Am Fuß getragene IMU: gyr_x..z (rad/s) im Sensorkoordinatensystem.</translation>
    </message>
    <message>
        <source>Events: t (s), type (ic, tc, min_vel), foot.</source>
        <translation>Ereignisse: t (s), type (ic, tc, min_vel), foot.</translation>
    </message>
    <message>
        <source>Strides (IC to next IC) as predicted annotations with confidence.</source>
        <translation>Doppelschritte (IC bis zum nächsten IC) als vorhergesagte Annotationen mit Konfidenz.</translation>
    </message>
</context>
<context>
    <name>athlos::events::GaitParametersProcessor</name>
    <message>
        <source>Gait parameters (foot IMU)</source>
        <translation>Gangparameter (Fuß-IMU)</translation>
    </message>
    <message>
        <source>Swings further apart have the foot standing between them: the strides end and start next to the standing phase.</source>
        <translation>Weiter auseinanderliegende Schwünge haben einen stehenden Fuß dazwischen: die Doppelschritte enden und beginnen neben der Standphase.</translation>
    </message>
    <message>
        <source>Moving average of the gyroscope norm whose minimum is the mid-stance (gaitmap NormZuptDetector: 0.15 s).</source>
        <translation>Gleitender Mittelwert der Gyroskopnorm, dessen Minimum der Mittelstand ist (gaitmap NormZuptDetector: 0,15 s).</translation>
    </message>
    <message>
        <source>Standing: gyroscope norm averaged over rest_window below this (gaitmap NormZuptDetector: 15 deg/s); pauses end strides, and the mean rate while standing is the gyroscope bias, removed before integration.</source>
        <translation>Stehen: über rest_window gemittelte Gyroskopnorm unter diesem Wert (gaitmap NormZuptDetector: 15 deg/s); Pausen beenden Doppelschritte, und die mittlere Drehrate im Stehen ist der Gyroskop-Bias, der vor der Integration entfernt wird.</translation>
    </message>
    <message>
        <source>A pause between two swings (below static_threshold at least this long) ends the stride before where the foot comes to rest and starts the next where it leaves, so that no stride contains the pause. Shorter than a stride, longer than the foot-flat phase of slow walking.</source>
        <translation>Eine Pause zwischen zwei Schwüngen (mindestens so lange unter static_threshold) beendet den Doppelschritt vor der Stelle, an der der Fuß zur Ruhe kommt, und beginnt den nächsten dort, wo er sie verlässt, sodass kein Doppelschritt die Pause enthält. Kürzer als ein Doppelschritt, länger als die Fußflachphase langsamen Gehens.</translation>
    </message>
    <message>
        <source>Shortest standing phase used for the gyroscope bias; 0: no bias removal.</source>
        <translation>Kürzeste Standphase, die für den Gyroskop-Bias verwendet wird; 0: keine Bias-Entfernung.</translation>
    </message>
    <message>
        <source>Next to a standing phase, the mid-stance is searched this long after the last swing and before the next one.</source>
        <translation>Neben einer Standphase wird der Mittelstand so lange nach dem letzten Schwung und vor dem nächsten gesucht.</translation>
    </message>
    <message>
        <source>Accelerometer average at a mid-stance that gives the up direction.</source>
        <translation>Mittelung des Beschleunigungsmessers bei einem Mittelstand, die die Aufwärtsrichtung liefert.</translation>
    </message>
    <message>
        <source>One row per stride: start, end, stride_length, stride_height, stride_time, stance_time, swing_time, cadence, gait_speed, max_toe_clearance, turning_angle.</source>
        <translation>Eine Zeile je Doppelschritt: start, end, stride_length, stride_height, stride_time, stance_time, swing_time, cadence, gait_speed, max_toe_clearance, turning_angle.</translation>
    </message>
    <message>
        <source>instant: per stride, zero velocity at the two mid-stance instants, drift removed linearly. rts: zero-velocity-aided error-state Kalman filter with Rauch-Tung-Striebel smoothing over the whole recording, zero velocity on every stance sample (Skog et al. 2010; gaitmap RtsKalman).</source>
        <translation>instant: je Schritt Nullgeschwindigkeit an den beiden Mittelstand-Zeitpunkten, Drift linear entfernt. rts: nullgeschwindigkeitsgestütztes Error-State-Kalman-Filter mit Rauch-Tung-Striebel-Glättung über die ganze Aufnahme, Nullgeschwindigkeit an jedem Sample der Standphase (Skog et al. 2010; gaitmap RtsKalman).</translation>
    </message>
    <message>
        <source>rts: a sample is stance (zero velocity) when the averaged gyroscope norm is at most this (gaitmap NormZuptDetector: 15 deg/s).</source>
        <translation>rts: ein Sample gehört zur Standphase (Nullgeschwindigkeit), wenn die gemittelte Gyroskop-Norm höchstens diesen Wert hat (gaitmap NormZuptDetector: 15 °/s).</translation>
    </message>
    <message>
        <source>rts: gyroscope process noise per sample.</source>
        <translation>rts: Prozessrauschen des Gyroskops je Sample.</translation>
    </message>
    <message>
        <source>rts: standard deviation of the zero-velocity pseudo-measurement (OpenShoe: 0.01 m/s).</source>
        <translation>rts: Standardabweichung der Nullgeschwindigkeits-Pseudomessung (OpenShoe: 0,01 m/s).</translation>
    </message>
    <message>
        <source>Strides between consecutive mid-stance (minimum-velocity) instants of a foot-mounted IMU and zero-velocity-aided integration (method rts: a Kalman smoother over the whole recording with zero velocity on every stance sample; method instant: per stride, levelled from gravity at each mid-stance, inclination and velocity drift removed linearly): stride length (horizontal) and height, stride, stance and swing time, cadence, gait speed, toe clearance and turning angle; plus the foot trajectory.</source>
        <translation>Doppelschritte zwischen aufeinanderfolgenden Standphasenmitten (minimale Geschwindigkeit) eines am Fuß getragenen IMU und Integration mit Nullgeschwindigkeits-Stützung (Methode rts: ein Kalman-Glätter über die ganze Aufnahme mit Nullgeschwindigkeit an jedem Standphasen-Sample; Methode instant: je Doppelschritt, an jeder Standphasenmitte aus der Schwerkraft horizontiert, Neigungs- und Geschwindigkeitsdrift linear entfernt): Schrittlänge (horizontal) und -höhe, Schritt-, Stand- und Schwungzeit, Kadenz, Ganggeschwindigkeit, Bodenfreiheit und Drehwinkel; dazu die Fußtrajektorie.</translation>
    </message>
    <message>
        <source>Foot-mounted IMU: acc_x..z (m/s^2), gyr_x..z (rad/s), in any sensor frame (ml_axis = auto finds the medio-lateral axis; give it when the recording is too short to tell).</source>
        <translation>Am Fuß getragenes IMU: acc_x..z (m/s^2), gyr_x..z (rad/s), in beliebigem Sensorsystem (ml_axis = auto findet die medio-laterale Achse; bei zu kurzen Aufnahmen angeben).</translation>
    </message>
    <message>
        <source>Foot (sensor) positions x, y, z (m): z up, heading 0 at the first mid-stance.</source>
        <translation>Fuß-(Sensor-)Positionen x, y, z (m): z nach oben, Kurs 0 in der ersten Standphasenmitte.</translation>
    </message>
    <message>
        <source>Largest averaged gyroscope norm accepted as the mid-stance before the first swing or after the last one, where the data may start or end in motion. Between two swings the quietest instant is always the mid-stance (a running foot still rolls at 2–4 rad/s there). gaitmap&apos;s static threshold is 15 deg/s (0.26 rad/s), but the quietest 0.15 s of a stance reaches 0.2–1.3 rad/s in gaitmap&apos;s own walk, so the default is 2 rad/s.</source>
        <translation>Größte gemittelte Gyroskopnorm, die als Mittelstand vor dem ersten Schwung oder nach dem letzten akzeptiert wird, wo die Daten in Bewegung beginnen oder enden können. Zwischen zwei Schwüngen ist der ruhigste Zeitpunkt immer der Mittelstand (ein laufender Fuß rollt dort noch mit 2–4 rad/s). Die statische Schwelle von gaitmap ist 15 deg/s (0,26 rad/s), doch die ruhigsten 0,15 s eines Stands erreichen in gaitmaps eigenem Gang 0,2–1,3 rad/s, daher ist die Vorgabe 2 rad/s.</translation>
    </message>
    <message>
        <source>rts: moving average of the gyroscope norm of the stance detector (gaitmap NormZuptDetector: 0.15 s). The samples within half of it around each mid-stance are stance while their average is at most zupt_threshold above the mid-stance&apos;s.</source>
        <translation>rts: gleitender Mittelwert der Gyroskop-Norm für die Erkennung der Standphase (gaitmap NormZuptDetector: 0,15 s). Die Samples innerhalb der halben Fensterlänge um jeden Mittelstand gelten als Standphase, solange ihr Mittelwert höchstens zupt_threshold über dem des Mittelstands liegt.</translation>
    </message>
    <message>
        <source>rts: accelerometer process noise per m/s^2 of |acceleration norm - g|: scale, impact and shoe errors grow with the motion, so the smoother corrects the velocity at push-off and landing. 0: evenly over the swing (version 4).</source>
        <translation>rts: Prozessrauschen des Beschleunigungsmessers je m/s^2 von |Beschleunigungsnorm - g|: Skalen-, Stoß- und Schuhfehler wachsen mit der Bewegung, daher korrigiert der Glätter die Geschwindigkeit beim Abstoßen und Aufsetzen. 0: gleichmäßig über den Schwung (Version 4).</translation>
    </message>
    <message>
        <source>rts: gyroscope process noise per rad/s of rotation rate.</source>
        <translation>rts: Prozessrauschen des Gyroskops je rad/s Drehrate.</translation>
    </message>
    <message>
        <source>rts: accelerometer process noise per sample in quiet phases: sensor noise and vibration (OpenShoe: 0.01 m/s^2 for white noise alone); acc_noise_dynamic adds the errors that come with the motion.</source>
        <translation>rts: Prozessrauschen des Beschleunigungsmessers je Sample in ruhigen Phasen: Sensorrauschen und Vibration (OpenShoe: 0,01 m/s^2 für weißes Rauschen allein); acc_noise_dynamic fügt die Fehler hinzu, die mit der Bewegung kommen.</translation>
    </message>
    <message>
        <source>Longest run of missing samples (empty cells, NaN) bridged by linear interpolation (0.05 s: 5 % of a walking stride); a longer one is refused.</source>
        <translation>Längste Folge fehlender Abtastwerte (leere Zellen, NaN), die linear interpoliert überbrückt wird (0,05 s: 5 % eines Doppelschritts beim Gehen); eine längere wird abgelehnt.</translation>
    </message>
</context>
<context>
    <name>athlos::events::GaitSummaryProcessor</name>
    <message>
        <source>Gait summary (steady state)</source>
        <translation>Gangzusammenfassung (eingeschwungener Zustand)</translation>
    </message>
    <message>
        <source>Strides whose |turning_angle| is larger are turns and left out (0.3 rad = 17°, the straight strides of this project&apos;s validation).</source>
        <translation>Doppelschritte mit größerem |turning_angle| sind Drehungen und werden ausgelassen (0,3 rad = 17°, die geraden Doppelschritte der Validierung dieses Projekts).</translation>
    </message>
    <message>
        <source>Strides left out at each end of a run of adjacent straight strides: gait initiation and termination (steady state, Lindemann et al. 2008).</source>
        <translation>An jedem Ende einer Folge aneinandergrenzender gerader Doppelschritte ausgelassene Doppelschritte: Gangbeginn und Gangende (eingeschwungener Zustand, Lindemann et al. 2008).</translation>
    </message>
    <message>
        <source>Stride table of one foot (gait-parameters).</source>
        <translation>Doppelschritt-Tabelle eines Fußes (gait-parameters).</translation>
    </message>
    <message>
        <source>Stride table of the other foot (gait-parameters); with it, both feet together and the symmetry index.</source>
        <translation>Doppelschritt-Tabelle des anderen Fußes (gait-parameters); mit ihr beide Füße zusammen und der Symmetrieindex.</translation>
    </message>
    <message>
        <source>One row per foot (and both): foot, strides, used, then per parameter &lt;p&gt;_mean, &lt;p&gt;_sd, &lt;p&gt;_cv (%) and, for two feet, &lt;p&gt;_si (%, in the row both).</source>
        <translation>Eine Zeile je Fuß (und both): foot, strides, used, dann je Parameter &lt;p&gt;_mean, &lt;p&gt;_sd, &lt;p&gt;_cv (%) und bei zwei Füßen &lt;p&gt;_si (%, in der Zeile both).</translation>
    </message>
    <message>
        <source>Which strides to summarise by their stride_height: all, level (|height| at most level_height), up or down (|height| at least stair_height); the others, transitions included, are left out like turns.</source>
        <translation>Welche Doppelschritte nach ihrer stride_height zusammengefasst werden: all, level (|Höhe| höchstens level_height), up oder down (|Höhe| mindestens stair_height); die anderen, Übergänge eingeschlossen, werden wie Drehungen ausgelassen.</translation>
    </message>
    <message>
        <source>Largest |stride_height| of a level stride (a third of a step; level strides drift by 0.02-0.03 m).</source>
        <translation>Größte |stride_height| eines ebenen Doppelschritts (ein Drittel einer Stufe; ebene Doppelschritte driften um 0,02-0,03 m).</translation>
    </message>
    <message>
        <source>Smallest |stride_height| of a stride on stairs: a stride climbs two steps of 0.14-0.19 m (DIN 18065), a transition (one step and a landing) less.</source>
        <translation>Kleinste |stride_height| eines Doppelschritts auf der Treppe: ein Doppelschritt steigt zwei Stufen von 0,14-0,19 m (DIN 18065), ein Übergang (eine Stufe und ein Podest) weniger.</translation>
    </message>
    <message>
        <source>Steady-state summary of the stride tables of gait-parameters, one foot or both: turning strides, strides on other ground than the chosen terrain (level, stairs up or down) and the first and last strides of every straight run left out, then per parameter the mean, standard deviation and coefficient of variation per foot, and for two feet both feet together with the symmetry index (Robinson et al. 1987).</source>
        <translation>Zusammenfassung der Doppelschritt-Tabellen von gait-parameters im eingeschwungenen Zustand, ein Fuß oder beide: Doppelschritte mit Drehung, Doppelschritte auf anderem Untergrund als dem gewählten (eben, Treppe auf oder ab) sowie der erste und letzte Doppelschritt jeder geraden Folge werden ausgelassen, dann je Parameter Mittelwert, Standardabweichung und Variationskoeffizient je Fuß und für zwei Füße beide Füße zusammen mit dem Symmetrieindex (Robinson et al. 1987).</translation>
    </message>
</context>
<context>
    <name>athlos::events::SimulateSkiingProcessor</name>
    <message>
        <source>Simulate skiing IMUs</source>
        <translation>Ski-IMUs simulieren</translation>
    </message>
    <message>
        <source>Skiing IMU recordings with ground truth: cross-country diagonal stride (ski IMU at &lt;output&gt;, pole IMU at &lt;output&gt;-pole; motionless thrusts, hilly track), a ski-mountaineering ascent (ski IMU, 18° track) or an alpine run (sacrum IMU, turns 22–32 m apart at 20 m/s on a 26° slope). The true cycles or turns are at &lt;output&gt;-truth.</source>
        <translation>Ski-IMU-Aufnahmen mit Referenz: Diagonalschritt im Langlauf (Ski-IMU unter &lt;output&gt;, Stock-IMU unter &lt;output&gt;-pole; ruhende Abstöße, hügelige Strecke), ein Skitouren-Aufstieg (Ski-IMU, 18°-Spur) oder eine Alpinfahrt (Kreuzbein-IMU, Schwünge 22–32 m auseinander bei 20 m/s auf einem 26°-Hang). Die wahren Zyklen oder Schwünge liegen unter &lt;output&gt;-truth.</translation>
    </message>
    <message>
        <source>Discipline.</source>
        <translation>Disziplin.</translation>
    </message>
    <message>
        <source>Random seed.</source>
        <translation>Zufallsstartwert.</translation>
    </message>
    <message>
        <source>Number of cycles (xc, skimo) or turns.</source>
        <translation>Anzahl der Zyklen (xc, skimo) oder Schwünge.</translation>
    </message>
    <message>
        <source>Ski IMU (xc, skimo) or sacrum IMU (alpine).</source>
        <translation>Ski-IMU (xc, skimo) oder Kreuzbein-IMU (alpine).</translation>
    </message>
    <message>
        <source>Pole IMU (xc only).</source>
        <translation>Stock-IMU (nur xc).</translation>
    </message>
    <message>
        <source>True cycles (thrust_start … pole_lift) or turns (start, end, side).</source>
        <translation>Wahre Zyklen (thrust_start … pole_lift) oder Schwünge (start, end, side).</translation>
    </message>
</context>
<context>
    <name>athlos::events::SimulateWristWalkProcessor</name>
    <message>
        <source>Simulate wrist walking</source>
        <translation>Gehen mit Handgelenksensor simulieren</translation>
    </message>
    <message>
        <source>Simulates a wrist-worn IMU and barometer during outdoor walking bouts (cadence changing over time, uphill, downhill and flat paths, arm swing, some bouts with the hand held still) and pauses (standing, arm gestures), with the truth: cadence, speed, grade, altitude and walking per 0.1 s.</source>
        <translation>Simuliert eine am Handgelenk getragene IMU und ein Barometer bei Gehabschnitten im Freien (Kadenz ändert sich mit der Zeit, bergauf, bergab und eben, Armschwung, einige Abschnitte mit ruhig gehaltener Hand) und Pausen (Stehen, Armgesten), mit der Referenz: Kadenz, Geschwindigkeit, Steigung, Höhe und Gehen je 0,1 s.</translation>
    </message>
    <message>
        <source>Random seed (deterministic).</source>
        <translation>Zufallsstartwert (deterministisch).</translation>
    </message>
    <message>
        <source>Length of the recording.</source>
        <translation>Länge der Aufnahme.</translation>
    </message>
    <message>
        <source>IMU sampling rate.</source>
        <translation>Abtastrate der IMU.</translation>
    </message>
    <message>
        <source>The walker&apos;s height (step length scales with it).</source>
        <translation>Körpergröße der gehenden Person (die Schrittlänge skaliert damit).</translation>
    </message>
    <message>
        <source>Lowest walking cadence.</source>
        <translation>Niedrigste Gehkadenz.</translation>
    </message>
    <message>
        <source>Highest walking cadence.</source>
        <translation>Höchste Gehkadenz.</translation>
    </message>
    <message>
        <source>Steepest path (rise over run) of a walking bout.</source>
        <translation>Steilster Weg (Steigung) eines Gehabschnitts.</translation>
    </message>
    <message>
        <source>Fraction of the time spent walking.</source>
        <translation>Zeitanteil des Gehens.</translation>
    </message>
    <message>
        <source>Accelerometer white noise (1 SD).</source>
        <translation>Weißes Rauschen des Beschleunigungsmessers (1 SD).</translation>
    </message>
    <message>
        <source>Barometer white noise (1 SD).</source>
        <translation>Weißes Rauschen des Barometers (1 SD).</translation>
    </message>
    <message>
        <source>Weather drift of the pressure (sign random).</source>
        <translation>Wetterbedingte Drift des Luftdrucks (Vorzeichen zufällig).</translation>
    </message>
    <message>
        <source>Wrist IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</source>
        <translation>Handgelenk-IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</translation>
    </message>
    <message>
        <source>Pressure (Pa) at 25 Hz.</source>
        <translation>Luftdruck (Pa) mit 25 Hz.</translation>
    </message>
    <message>
        <source>Truth: cadence (steps/min), speed (m/s), grade, altitude (m), walking (1/0).</source>
        <translation>Referenz: Kadenz (Schritte/min), Geschwindigkeit (m/s), Steigung, Höhe (m), Gehen (1/0).</translation>
    </message>
</context>
<context>
    <name>athlos::events::SkimoPhasesProcessor</name>
    <message>
        <source>Ski-mountaineering phases</source>
        <translation>Phasen im Skitourengehen</translation>
    </message>
    <message>
        <source>Ski-mountaineering ascent from a ski IMU (Fasel 2017 ch. 4): motionless phases at the minima of the speed integrated without resets, speed with the drift on the central 50 % of each phase removed, phases refined where the speed is below zero_speed; per cycle duration, speed, length, elevation gain and slope angle. The recording must start with the ski still.</source>
        <translation>Skitouren-Aufstieg aus einer Ski-IMU (Fasel 2017 Kap. 4): Ruhephasen an den Minima der ohne Rücksetzen integrierten Geschwindigkeit, Geschwindigkeit mit der über die mittleren 50 % jeder Phase entfernten Drift, Phasen verfeinert, wo die Geschwindigkeit unter zero_speed liegt; je Zyklus Dauer, Geschwindigkeit, Länge, Höhengewinn und Hangwinkel. Die Aufnahme muss mit ruhendem Ski beginnen.</translation>
    </message>
    <message>
        <source>Ski-mounted IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</source>
        <translation>Am Ski montierte IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</translation>
    </message>
    <message>
        <source>Per cycle: still_start, still_end, end (s), duration (s), speed (m/s), length (m), elevation (m), slope (rad); attribute elevation_gain (m).</source>
        <translation>Je Zyklus: still_start, still_end, end (s), duration (s), speed (m/s), length (m), elevation (m), slope (rad); Attribut elevation_gain (m).</translation>
    </message>
    <message>
        <source>Cycles and motionless phases as predicted annotations.</source>
        <translation>Zyklen und Ruhephasen als vorhergesagte Annotationen.</translation>
    </message>
</context>
<context>
    <name>athlos::events::WristCadenceProcessor</name>
    <message>
        <source>Wrist walking cadence</source>
        <translation>Gehkadenz vom Handgelenk</translation>
    </message>
    <message>
        <source>Walking cadence from a wrist-worn accelerometer (Fasel et al. 2017): comb filter on the log spectrum of 6 s windows of the acceleration norm (harmonics +1, half harmonics -1, stride frequency 0.4-2 Hz), tracked over time; walking detected from the comb likelihood and the norm&apos;s variability. One row per second.</source>
        <translation>Gehkadenz aus einem am Handgelenk getragenen Beschleunigungsmesser (Fasel et al. 2017): Kammfilter auf dem logarithmischen Spektrum von 6-s-Fenstern der Beschleunigungsnorm (Harmonische +1, halbe Harmonische −1, Doppelschrittfrequenz 0,4–2 Hz), über die Zeit verfolgt; Gehen erkannt aus der Kamm-Likelihood und der Variabilität der Norm. Eine Zeile je Sekunde.</translation>
    </message>
    <message>
        <source>Window length (thesis eq. 12.1: 6 s, 120 samples at 20 Hz; at most 12.8 s, the FFT of 256).</source>
        <translation>Fensterlänge (Arbeit Gl. 12.1: 6 s, 120 Abtastwerte bei 20 Hz; höchstens 12,8 s, die FFT mit 256).</translation>
    </message>
    <message>
        <source>Window shift (thesis: 1 s).</source>
        <translation>Fensterversatz (Arbeit: 1 s).</translation>
    </message>
    <message>
        <source>Walking needs the harmonics of the comb&apos;s stride frequency to exceed their neighbouring half harmonics by this much on average (natural log of the amplitude ratio; ours, not in the thesis, which segmented walking by hand: see docs/validation/wrist-walking.md).</source>
        <translation>Gehen erfordert, dass die Harmonischen der Doppelschrittfrequenz des Kamms ihre benachbarten halben Harmonischen im Mittel um so viel übertreffen (natürlicher Logarithmus des Amplitudenverhältnisses; eigene Wahl, nicht aus der Arbeit, die das Gehen von Hand segmentierte: siehe docs/validation/wrist-walking.md).</translation>
    </message>
    <message>
        <source>Walking needs this SD of the acceleration norm in the window (ours: standing is below 0.1 m/s^2).</source>
        <translation>Gehen erfordert diese SD der Beschleunigungsnorm im Fenster (eigene Wahl: Stehen liegt unter 0,1 m/s^2).</translation>
    </message>
    <message>
        <source>Tracking: a stride frequency further than this from the previous one triggers the search in ranges A and B (thesis eq. 12.4: 0.07 Hz).</source>
        <translation>Verfolgung: eine Doppelschrittfrequenz, die weiter als dies von der vorigen entfernt ist, löst die Suche in den Bereichen A und B aus (Arbeit Gl. 12.4: 0,07 Hz).</translation>
    </message>
    <message>
        <source>Tracking: half-width of range B around the previous step frequency (eq. 12.4: 0.14 Hz).</source>
        <translation>Verfolgung: halbe Breite von Bereich B um die vorige Schrittfrequenz (Gl. 12.4: 0,14 Hz).</translation>
    </message>
    <message>
        <source>Weight of the previous cadence in the low-pass c[n] = a c[n-1] + (1-a) c[n] (thesis: 0.33).</source>
        <translation>Gewicht der vorigen Kadenz im Tiefpass c[n] = a c[n-1] + (1-a) c[n] (Arbeit: 0,33).</translation>
    </message>
    <message>
        <source>Windows in a row whose comb maximum lies near neither the tracked stride nor step frequency before the track restarts from the maximum (ours, not in the thesis; 1000: never).</source>
        <translation>Fenster in Folge, deren Kamm-Maximum weder nahe der verfolgten Doppelschritt- noch der Schrittfrequenz liegt, bevor die Verfolgung beim Maximum neu beginnt (eigene Wahl, nicht aus der Arbeit; 1000: nie).</translation>
    </message>
    <message>
        <source>Wrist IMU with acc_x..z (m/s^2) sampled at 20 Hz or faster; any orientation.</source>
        <translation>Handgelenk-IMU mit acc_x..z (m/s^2), abgetastet mit 20 Hz oder schneller; beliebige Orientierung.</translation>
    </message>
    <message>
        <source>Per window centre: cadence (steps/min, NaN when not walking), walking (1/0), likelihood, norm_max and norm_std (m/s^2).</source>
        <translation>Je Fenstermitte: cadence (Schritte/min, NaN, wenn nicht gegangen wird), walking (1/0), likelihood, norm_max und norm_std (m/s^2).</translation>
    </message>
</context>
<context>
    <name>athlos::events::WristSpeedProcessor</name>
    <message>
        <source>Wrist walking speed</source>
        <translation>Gehgeschwindigkeit vom Handgelenk</translation>
    </message>
    <message>
        <source>Walking speed per cadence window from a trained wrist-speed model (Fasel et al. 2017): the nearest of the k-means centroids picks the linear model of the features max*std of the acceleration norm, cadence, barometric pressure change over 9 s and height.</source>
        <translation>Gehgeschwindigkeit je Kadenzfenster aus einem trainierten wrist-speed-Modell (Fasel et al. 2017): der nächste der k-means-Zentroide wählt das lineare Modell der Merkmale max*std der Beschleunigungsnorm, Kadenz, Luftdruckänderung über 9 s und Körpergröße.</translation>
    </message>
    <message>
        <source>Output of wrist-cadence.</source>
        <translation>Ausgabe von wrist-cadence.</translation>
    </message>
    <message>
        <source>Barometric pressure (Pa) of the same wrist sensor.</source>
        <translation>Luftdruck (Pa) desselben Handgelenksensors.</translation>
    </message>
    <message>
        <source>A model from wrist-speed-train.</source>
        <translation>Ein Modell aus wrist-speed-train.</translation>
    </message>
    <message>
        <source>speed (m/s, NaN when not walking) and the cluster used, per cadence window.</source>
        <translation>Geschwindigkeit (m/s, NaN, wenn nicht gegangen wird) und der verwendete Cluster, je Kadenzfenster.</translation>
    </message>
</context>
<context>
    <name>athlos::events::WristSpeedTrainProcessor</name>
    <message>
        <source>Train wrist walking speed</source>
        <translation>Gehgeschwindigkeit vom Handgelenk trainieren</translation>
    </message>
    <message>
        <source>Trains the wrist walking-speed model (Fasel et al. 2017): features max*std of the acceleration norm, cadence, barometric pressure change over 9 s and height per walking window; 16 k-means clusters, each with its own linear model fitted to a reference speed. Give an earlier model to add this walker&apos;s windows to its training rows.</source>
        <translation>Trainiert das Gehgeschwindigkeitsmodell für das Handgelenk (Fasel et al. 2017): Merkmale max*std der Beschleunigungsnorm, Kadenz, Luftdruckänderung über 9 s und Körpergröße je Gehfenster; 16 k-means-Cluster, jeder mit eigenem linearem Modell, angepasst an eine Referenzgeschwindigkeit. Geben Sie ein früheres Modell an, um die Fenster dieser gehenden Person zu dessen Trainingszeilen hinzuzufügen.</translation>
    </message>
    <message>
        <source>k-means clusters, each with a linear model (thesis: 16).</source>
        <translation>k-means-Cluster, jeder mit einem linearen Modell (Arbeit: 16).</translation>
    </message>
    <message>
        <source>A cluster with fewer training windows uses the global linear model.</source>
        <translation>Ein Cluster mit weniger Trainingsfenstern verwendet das globale lineare Modell.</translation>
    </message>
    <message>
        <source>Seed of the k-means++ initialisation (deterministic training).</source>
        <translation>Startwert der k-means++-Initialisierung (deterministisches Training).</translation>
    </message>
    <message>
        <source>Windows whose mean reference speed is below this are not used.</source>
        <translation>Fenster, deren mittlere Referenzgeschwindigkeit darunter liegt, werden nicht verwendet.</translation>
    </message>
    <message>
        <source>Output of wrist-cadence.</source>
        <translation>Ausgabe von wrist-cadence.</translation>
    </message>
    <message>
        <source>Barometric pressure (Pa) of the same wrist sensor.</source>
        <translation>Luftdruck (Pa) desselben Handgelenksensors.</translation>
    </message>
    <message>
        <source>Reference walking speed: a stream with a column &apos;speed&apos; (m/s), e.g. from GNSS.</source>
        <translation>Referenz-Gehgeschwindigkeit: ein Datenstrom mit einer Spalte „speed“ (m/s), z. B. aus GNSS.</translation>
    </message>
    <message>
        <source>An earlier model whose training windows are kept.</source>
        <translation>Ein früheres Modell, dessen Trainingsfenster erhalten bleiben.</translation>
    </message>
    <message>
        <source>Training windows (t, max_x_std, cadence, pressure_change, height, speed) with the model in the attributes.</source>
        <translation>Trainingsfenster (t, max_x_std, cadence, pressure_change, height, speed) mit dem Modell in den Attributen.</translation>
    </message>
</context>
<context>
    <name>athlos::events::XcSkiingCyclesProcessor</name>
    <message>
        <source>Cross-country skiing cycles</source>
        <translation>Zyklen im Skilanglauf</translation>
    </message>
    <message>
        <source>Diagonal-stride cycles from a ski IMU (Fasel 2017 ch. 3): motionless thrust phases, ski inclination from the medio-lateral gyroscope re-anchored in each thrust, speed from the forward acceleration with zero-velocity updates, thrust start and end, gliding start (maximum speed), cycle duration, speed, length, elevation and slope; with a pole IMU also pole plant (start of the shock) and pole lift (acceleration peak). Writes a per-cycle table and predicted annotations.</source>
        <translation>Diagonalschritt-Zyklen aus einer Ski-IMU (Fasel 2017 Kap. 3): ruhende Abstoßphasen, Skineigung aus dem medio-lateralen Gyroskop, in jedem Abstoß neu verankert, Geschwindigkeit aus der Vorwärtsbeschleunigung mit Nullgeschwindigkeits-Updates, Beginn und Ende des Abstoßes, Beginn des Gleitens (maximale Geschwindigkeit), Zyklusdauer, Geschwindigkeit, Länge, Höhe und Neigung; mit einer Stock-IMU auch Stockeinsatz (Beginn des Stoßes) und Stockabheben (Beschleunigungsspitze). Schreibt eine Tabelle je Zyklus und vorhergesagte Annotationen.</translation>
    </message>
    <message>
        <source>Ski-mounted IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</source>
        <translation>Am Ski montierte IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</translation>
    </message>
    <message>
        <source>Pole-mounted IMU of the same side (optional): pole plant and lift.</source>
        <translation>Am Stock montierte IMU derselben Seite (optional): Stockeinsatz und -abheben.</translation>
    </message>
    <message>
        <source>Per cycle: thrust_start, thrust_end, glide_start, end (s), duration (s), speed (m/s), length (m), elevation (m), slope (rad), pole_plant, pole_lift (s).</source>
        <translation>Je Zyklus: thrust_start, thrust_end, glide_start, end (s), duration (s), speed (m/s), length (m), elevation (m), slope (rad), pole_plant, pole_lift (s).</translation>
    </message>
    <message>
        <source>Cycles, thrust phases, gliding starts and pole pushes as predicted annotations.</source>
        <translation>Zyklen, Abstoßphasen, Gleitbeginne und Stockschübe als vorhergesagte Annotationen.</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::DriftReductionProcessor</name>
    <message>
        <source>Drift reduction (joints)</source>
        <translation>Driftreduktion (Gelenke)</translation>
    </message>
    <message>
        <source>Segment of each input pair, in order; the first must be sacrum. Links: sacrum → sternum, sacrum → &lt;side&gt;-thigh → &lt;side&gt;-shank → &lt;side&gt;-foot.</source>
        <translation>Segment jedes Eingabepaars, der Reihe nach; das erste muss sacrum sein. Verbindungen: sacrum → sternum, sacrum → &lt;side&gt;-thigh → &lt;side&gt;-shank → &lt;side&gt;-foot.</translation>
    </message>
    <message>
        <source>Valid-sample thresholds: on-snow (|ã| &gt; 8 m/s², ||ã_d| − |ã_p|| &lt; 2.5 m/s², Fasel 2017 Eqs. 5.6–5.8) or indoor (|ã| &gt; 6 m/s², relative difference &lt; 0.2, Eqs. 6.9–6.11). The parameters below override the preset.</source>
        <translation>Schwellen für gültige Abtastwerte: on-snow (|ã| &gt; 8 m/s², ||ã_d| − |ã_p|| &lt; 2,5 m/s², Fasel 2017 Gl. 5.6–5.8) oder indoor (|ã| &gt; 6 m/s², relative Differenz &lt; 0,2, Gl. 6.9–6.11). Die folgenden Parameter überschreiben die Voreinstellung.</translation>
    </message>
    <message>
        <source>Minimum |ã_d|, |ã_p| (Eqs. 5.7–5.8; preset).</source>
        <translation>Minimum von |ã_d|, |ã_p| (Gl. 5.7–5.8; Voreinstellung).</translation>
    </message>
    <message>
        <source>Maximum ||ã_d| − |ã_p|| (Eq. 5.6; preset).</source>
        <translation>Maximum von ||ã_d| − |ã_p|| (Gl. 5.6; Voreinstellung).</translation>
    </message>
    <message>
        <source>Maximum ||ã_d| − |ã_p|| / mean norm, 0 = not used (Eq. 6.11; preset).</source>
        <translation>Maximum von ||ã_d| − |ã_p|| / mittlere Norm, 0 = nicht verwendet (Gl. 6.11; Voreinstellung).</translation>
    </message>
    <message>
        <source>Cut-off of the zero-phase 2nd-order Butterworth low-pass of ω (Eqs. 5.3–5.4).</source>
        <translation>Grenzfrequenz des nullphasigen Butterworth-Tiefpasses 2. Ordnung für ω (Gl. 5.3–5.4).</translation>
    </message>
    <message>
        <source>Samples with |ω_proximal| above this fit the sensor-to-joint vectors (Eq. 5.5, 40°/s).</source>
        <translation>Abtastwerte mit |ω_proximal| über diesem Wert passen die Sensor-Gelenk-Vektoren an (Gl. 5.5, 40°/s).</translation>
    </message>
    <message>
        <source>Half width of the Markley mean of the drift (1.25 s, Fasel 2017 ch. 5).</source>
        <translation>Halbe Breite des Markley-Mittelwerts der Drift (1,25 s, Fasel 2017 Kap. 5).</translation>
    </message>
    <message>
        <source>Drift of a window: wahba — the rotation that best maps all its valid ã_d onto ã_p (least squares); markley — per-sample smallest rotation (Fasel 2017 Eqs. 5.9–5.11) averaged with the Markley quaternion mean, as in the thesis (biased here: docs/validation/drift-reduction.md).</source>
        <translation>Drift eines Fensters: wahba — die Rotation, die alle gültigen ã_d am besten auf ã_p abbildet (kleinste Quadrate); markley — je Abtastwert die kleinste Rotation (Fasel 2017 Gl. 5.9–5.11), gemittelt mit dem Markley-Quaternionenmittel wie in der Arbeit (hier verzerrt: docs/validation/drift-reduction.md).</translation>
    </message>
    <message>
        <source>Second pass on horizontal components (Eqs. 6.12–6.13).</source>
        <translation>Zweiter Durchgang auf den horizontalen Komponenten (Gl. 6.12–6.13).</translation>
    </message>
    <message>
        <source>Minimum horizontal norm in the azimuth pass (0.6 m/s²).</source>
        <translation>Minimale horizontale Norm im Azimut-Durchgang (0,6 m/s²).</translation>
    </message>
    <message>
        <source>Remove a constant heading offset per joint first (needed for 6D orientations, whose headings are independent).</source>
        <translation>Zuerst einen konstanten Richtungsversatz je Gelenk entfernen (nötig für 6D-Orientierungen, deren Richtungen unabhängig sind).</translation>
    </message>
    <message>
        <source>Joint drift reduction (Fasel 2017 ch. 5–6).</source>
        <translation>Gelenk-Driftreduktion (Fasel 2017 Kap. 5–6).</translation>
    </message>
    <message>
        <source>Rest detection: gyroscope deviation threshold (as in orientation).</source>
        <translation>Ruheerkennung: Schwelle für die Gyroskopabweichung (wie in orientation).</translation>
    </message>
    <message>
        <source>Rest detection: accelerometer deviation threshold.</source>
        <translation>Ruheerkennung: Schwelle für die Beschleunigungsabweichung.</translation>
    </message>
    <message>
        <source>Orientation (qw..qz) of the segment named at this place of `segments`.</source>
        <translation>Orientierung (qw..qz) des Segments, das an dieser Stelle von `segments` genannt ist.</translation>
    </message>
    <message>
        <source>IMU stream (acc_x..z, gyr_x..z) of the same sensor.</source>
        <translation>IMU-Datenstrom (acc_x..z, gyr_x..z) desselben Sensors.</translation>
    </message>
    <message>
        <source>Corrected sacrum orientation, same columns as its input.</source>
        <translation>Korrigierte Orientierung des Kreuzbeins, dieselben Spalten wie ihre Eingabe.</translation>
    </message>
    <message>
        <source>Corrected orientation of this segment.</source>
        <translation>Korrigierte Orientierung dieses Segments.</translation>
    </message>
    <message>
        <source>Reduces the orientation drift of body-worn sensors after the recording (Fasel 2017 ch. 2, 5, 6): inclination at rest instants spread by SLERP between them, then joint drift reduction — two segments linked by a joint must see the same joint-centre acceleration; sensor-to-joint vectors by Nelder–Mead, the drift between the two virtual accelerations estimated over ±1.25 s windows, corrected from the sacrum to the thighs, shanks and feet and to the sternum, then a second pass on horizontal components for the azimuth. Inputs: (orientation, imu) per segment in the order of `segments`. Velocity resets for foot/ski sensors: velocity-reset, on any of the outputs.</source>
        <translation>Verringert nach der Aufnahme die Orientierungsdrift körpergetragener Sensoren (Fasel 2017 Kap. 2, 5, 6): Neigung in Ruhemomenten, per SLERP dazwischen verteilt, dann Gelenk-Driftreduktion — zwei über ein Gelenk verbundene Segmente müssen dieselbe Gelenkzentrumsbeschleunigung sehen; Sensor-Gelenk-Vektoren per Nelder–Mead, die Drift zwischen den beiden virtuellen Beschleunigungen über ±1,25-s-Fenster geschätzt, korrigiert vom Sakrum zu Oberschenkeln, Unterschenkeln und Füßen sowie zum Sternum, danach ein zweiter Durchgang auf den horizontalen Komponenten für den Azimut. Eingänge: (orientation, imu) je Segment in der Reihenfolge von `segments`. Geschwindigkeits-Resets für Fuß-/Skisensoren: velocity-reset, auf jedem der Ausgänge.</translation>
    </message>
    <message>
        <source>The joint heading is fitted on samples whose horizontal ã exceed azimuth_min_norm (Eqs. 6.12–6.13); below this weighted mean resultant length of their heading differences (circular statistics, Mardia &amp; Jupp 2000; 0.5 ≈ 68° circular SD), or with fewer samples than a window needs, the heading is unobservable and the joint is left uncorrected (attribute heading_aligned=false: align it with joint-angles heading=align-start).</source>
        <translation>Die Gelenk-Kursrichtung wird an Samples angepasst, deren horizontales ã azimuth_min_norm übersteigt (Gl. 6.12–6.13); unterhalb dieser gewichteten mittleren resultierenden Länge ihrer Kursdifferenzen (zirkuläre Statistik, Mardia &amp; Jupp 2000; 0,5 ≈ 68° zirkuläre Standardabweichung) oder mit weniger Samples, als ein Fenster braucht, ist die Kursrichtung nicht beobachtbar und das Gelenk bleibt unkorrigiert (Attribut heading_aligned=false: mit joint-angles heading=align-start ausrichten).</translation>
    </message>
    <message>
        <source>Correct the inclination at rest instants, spread by SLERP between them (Fasel 2017 Eq. 2.7). Its model is an inclination error that grows between rests, as a gyroscope integration&apos;s: auto = only when every orientation input is a strap-down integration (attribute algorithm=strapdown). A filter that corrects its inclination with the accelerometer (vqf, madgwick, …) already uses the rests, and spreading its transient error at a rest back over the motion made the inclination worse (docs/validation/drift-reduction.md).</source>
        <translation>Die Neigung an Ruhezeitpunkten korrigieren, per SLERP dazwischen verteilt (Fasel 2017 Gl. 2.7). Ihr Modell ist ein Neigungsfehler, der zwischen den Ruhephasen wächst, wie bei einer Gyroskop-Integration: auto = nur wenn jede Orientierungseingabe eine Strapdown-Integration ist (Attribut algorithm=strapdown). Ein Filter, der seine Neigung mit dem Beschleunigungsmesser korrigiert (vqf, madgwick, …), nutzt die Ruhephasen bereits, und seinen vorübergehenden Fehler in einer Ruhephase über die Bewegung davor zu verteilen, verschlechterte die Neigung (docs/validation/drift-reduction.md).</translation>
    </message>
    <message>
        <source>The drift estimates of the correction passes use every k-th sample, k the largest whole number with rate / k ≥ this; the correction applies to every sample. 0 = every sample, else at least 20 Hz. Preset: on-snow 100 Hz (skiing at 500 Hz: joint angles within 0.01° of every sample), indoor 0 (walking has few valid samples).</source>
        <translation>Die Driftschätzungen der Korrekturdurchgänge verwenden jedes k-te Sample, k die größte ganze Zahl mit Rate / k ≥ diesem Wert; die Korrektur gilt für jedes Sample. 0 = jedes Sample, sonst mindestens 20 Hz. Vorgabe: on-snow 100 Hz (Skifahren mit 500 Hz: Gelenkwinkel innerhalb 0,01° von jedem Sample), indoor 0 (Gehen hat wenige gültige Samples).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::FunctionalCalibrationProcessor</name>
    <message>
        <source>Functional calibration (protocol)</source>
        <translation>Funktionelle Kalibrierung (Protokoll)</translation>
    </message>
    <message>
        <source>Sensor-to-segment mounts from the whole functional calibration protocol in one recording: upright standing, squats, trunk rotations, hip ab/adduction per leg and the optional arm swings, found automatically (or from annotations). Gravity gives each segment&apos;s superior axis, the principal axis of the angular velocity its medio-lateral axis (squats: pelvis, trunk, upper back, head, thighs, shanks; arm swings: upper arms) or antero-posterior axis (ab/adduction: feet; arm swings: forearms). Writes a segment-calibration table for joint-angles and body-com and a quality table (dispersion between repetitions, orthogonality, CMC).</source>
        <translation>Sensor-Segment-Montagen aus dem ganzen funktionellen Kalibrierprotokoll in einer Aufnahme: aufrechtes Stehen, Kniebeugen, Rumpfrotationen, Hüft-Ab-/Adduktion je Bein und die optionalen Armschwünge, automatisch gefunden (oder aus Annotationen). Die Schwerkraft liefert die superiore Achse jedes Segments, die Hauptachse der Winkelgeschwindigkeit seine medio-laterale Achse (Kniebeugen: Becken, Rumpf, oberer Rücken, Kopf, Oberschenkel, Unterschenkel; Armschwünge: Oberarme) oder antero-posteriore Achse (Ab-/Adduktion: Füße; Armschwünge: Unterarme). Schreibt eine segment-calibration-Tabelle für joint-angles und body-com und eine Qualitätstabelle (Streuung zwischen Wiederholungen, Orthogonalität, CMC).</translation>
    </message>
    <message>
        <source>Segment of each input IMU, in input order: sacrum (pelvis, lower-back), sternum (trunk), upper-back, head, right-/left-thigh, right-/left-shank, right-/left-foot, right-/left-upper-arm, right-/left-forearm.</source>
        <translation>Segment jeder Eingabe-IMU in der Reihenfolge der Eingaben: sacrum (Becken, lower-back), sternum (Rumpf), upper-back (oberer Rücken), head (Kopf), right-/left-thigh, right-/left-shank, right-/left-foot, right-/left-upper-arm (Oberarm), right-/left-forearm (Unterarm).</translation>
    </message>
    <message>
        <source>Movements given by hand, e.g. &apos;squats=12-24; right-abduction=40-49&apos; (s); they override the detection and the annotations.</source>
        <translation>Von Hand angegebene Bewegungen, z. B. „squats=12-24; right-abduction=40-49“ (s); sie ersetzen die Erkennung und die Annotationen.</translation>
    </message>
    <message>
        <source>Take interval annotations of the recording labelled upright, squats, trunk-rotations, right-abduction, left-abduction or arm-swings as the movements.</source>
        <translation>Intervall-Annotationen der Aufnahme mit den Bezeichnungen upright, squats, trunk-rotations, right-abduction, left-abduction oder arm-swings als Bewegungen übernehmen.</translation>
    </message>
    <message>
        <source>Rest: every sensor&apos;s angular rate (0.5 s mean) below this (11°/s).</source>
        <translation>Ruhe: die Drehrate jedes Sensors (Mittel über 0,5 s) unter diesem Wert (11°/s).</translation>
    </message>
    <message>
        <source>Shortest upright standing (the protocol asks for 10 s; Fasel ch. 6).</source>
        <translation>Kürzestes aufrechtes Stehen (das Protokoll verlangt 10 s; Fasel Kap. 6).</translation>
    </message>
    <message>
        <source>Rest that separates two movements.</source>
        <translation>Ruhe, die zwei Bewegungen trennt.</translation>
    </message>
    <message>
        <source>RMS angular rate above which a segment takes part in a movement (8°/s).</source>
        <translation>RMS-Drehrate, über der ein Segment an einer Bewegung teilnimmt (8°/s).</translation>
    </message>
    <message>
        <source>Ab/adduction: the standing leg&apos;s RMS rate below this share of the moving leg&apos;s.</source>
        <translation>Ab-/Adduktion: die RMS-Drehrate des Standbeins unter diesem Anteil der des bewegten Beins.</translation>
    </message>
    <message>
        <source>Trunk rotations: largest angle between the sternum&apos;s turning axis and gravity; squats and ab/adduction: smallest angle from the horizontal plane is 90° minus it.</source>
        <translation>Rumpfrotationen: größter Winkel zwischen der Drehachse des Brustbeins und der Schwerkraft; Kniebeugen und Ab-/Adduktion: der kleinste Winkel zur horizontalen Ebene ist 90° minus dieser Wert.</translation>
    </message>
    <message>
        <source>Repetitions each movement needs (the protocol&apos;s ×3, spec §4).</source>
        <translation>Wiederholungen, die jede Bewegung braucht (×3 im Protokoll, Spezifikation §4).</translation>
    </message>
    <message>
        <source>Largest dispersion χ of the functional axis between repetitions (10°; Fasel Table 6.3 reports up to 5.5° for the shank).</source>
        <translation>Größte Streuung χ der funktionellen Achse zwischen Wiederholungen (10°; Fasel Tabelle 6.3 nennt bis 5,5° für den Unterschenkel).</translation>
    </message>
    <message>
        <source>Largest angle between the functional axis and the plane perpendicular to gravity (30°; the simulated shank&apos;s coupled rotation tilts it by ≈ 8°).</source>
        <translation>Größter Winkel zwischen der funktionellen Achse und der Ebene senkrecht zur Schwerkraft (30°; die gekoppelte Rotation des simulierten Unterschenkels neigt sie um ≈ 8°).</translation>
    </message>
    <message>
        <source>IMU of the first segment (acc, gyr).</source>
        <translation>IMU des ersten Segments (acc, gyr).</translation>
    </message>
    <message>
        <source>IMU of segment %1.</source>
        <translation>IMU von Segment %1.</translation>
    </message>
    <message>
        <source>segment, qw, qx, qy, qz (segment to sensor), axis_share, orthogonality (rad).</source>
        <translation>segment, qw, qx, qy, qz (Segment → Sensor), axis_share, orthogonality (rad).</translation>
    </message>
    <message>
        <source>The right side&apos;s mounts under the names joint-angles reads: pelvis, thorax, head, thigh, shank, foot, upper-arm, forearm.</source>
        <translation>Die Montagen der rechten Seite unter den Namen, die joint-angles liest: pelvis, thorax, head, thigh, shank, foot, upper-arm, forearm.</translation>
    </message>
    <message>
        <source>The left side&apos;s mounts (pelvis, thorax, head, thigh, shank, foot, upper-arm, forearm).</source>
        <translation>Die Montagen der linken Seite (pelvis, thorax, head, thigh, shank, foot, upper-arm, forearm).</translation>
    </message>
    <message>
        <source>Per segment: movement, repetitions, dispersion χ, orthogonality, cross_orthogonality (rad), cmc, begin, end (s).</source>
        <translation>Je Segment: movement, repetitions, Streuung χ, orthogonality, cross_orthogonality (rad), cmc, begin, end (s).</translation>
    </message>
    <message>
        <source>Per movement and repetition: movement, repetition (0 = whole), begin, end (s), given.</source>
        <translation>Je Bewegung und Wiederholung: movement, repetition (0 = ganz), begin, end (s), given.</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::GnssImuProcessor</name>
    <message>
        <source>GNSS/IMU fusion</source>
        <translation>GNSS/IMU-Fusion</translation>
    </message>
    <message>
        <source>Loosely-coupled GNSS/IMU extended Kalman filter (Kim et al., Sensors 2023): position, velocity and attitude in a local ENU frame from the first fix, driven by the IMU at its rate and corrected by GNSS position (and velocity) at theirs; output at the IMU rate with horizontal speed and distance.</source>
        <translation>Lose gekoppelter erweiterter GNSS/IMU-Kalman-Filter (Kim et al., Sensors 2023): Position, Geschwindigkeit und Lage in einem lokalen ENU-System ab der ersten Position, angetrieben von der IMU mit deren Rate und korrigiert durch GNSS-Position (und -Geschwindigkeit) mit deren Rate; Ausgabe mit der IMU-Rate mit horizontaler Geschwindigkeit und Distanz.</translation>
    </message>
    <message>
        <source>Inclination source: ekf (the EKF&apos;s own quaternion, corrected through the GNSS velocity; best on sprints), orientation (the VQF-class filter) or kalman (the seed&apos;s quaternion Kalman filter). Heading always comes from the EKF.</source>
        <translation>Quelle der Neigung: ekf (das eigene Quaternion des EKF, über die GNSS-Geschwindigkeit korrigiert; am besten bei Sprints), orientation (der Filter der VQF-Klasse) oder kalman (der Quaternionen-Kalman-Filter der Quelle). Die Richtung kommt immer aus dem EKF.</translation>
    </message>
    <message>
        <source>Process noise of the specific force (includes attitude errors).</source>
        <translation>Prozessrauschen der spezifischen Kraft (schließt Lagefehler ein).</translation>
    </message>
    <message>
        <source>GNSS horizontal position noise per axis.</source>
        <translation>Rauschen der horizontalen GNSS-Position je Achse.</translation>
    </message>
    <message>
        <source>GNSS vertical position noise.</source>
        <translation>Rauschen der vertikalen GNSS-Position.</translation>
    </message>
    <message>
        <source>GNSS velocity noise per axis.</source>
        <translation>Rauschen der GNSS-Geschwindigkeit je Achse.</translation>
    </message>
    <message>
        <source>Use GNSS velocity columns when present.</source>
        <translation>GNSS-Geschwindigkeitsspalten verwenden, wenn vorhanden.</translation>
    </message>
    <message>
        <source>Local gravity.</source>
        <translation>Lokale Schwerebeschleunigung.</translation>
    </message>
    <message>
        <source>IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</source>
        <translation>IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).</translation>
    </message>
    <message>
        <source>GNSS: lat, lon, alt[, vn, ve, vd] or x, y, z[, vx, vy, vz] (ENU), same clock as the IMU.</source>
        <translation>GNSS: lat, lon, alt[, vn, ve, vd] oder x, y, z[, vx, vy, vz] (ENU), dieselbe Uhr wie die IMU.</translation>
    </message>
    <message>
        <source>x, y, z, vx, vy, vz (ENU from the first fix), qw..qz, speed (m/s, horizontal), distance (m).</source>
        <translation>x, y, z, vx, vy, vz (ENU ab der ersten Position), qw..qz, speed (m/s, horizontal), distance (m).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::ImuCalibrationProcessor</name>
    <message>
        <source>IMU calibration</source>
        <translation>IMU-Kalibrierung</translation>
    </message>
    <message>
        <source>Gyroscope offset from rest periods, accelerometer offset and scale from at least six static positions (each axis up and down), magnetometer hard/soft iron from an ellipsoid fit, and a saturation check. Writes the calibrated stream and the calibration table (&lt;output&gt;-calibration); given a calibration table as second input it applies that instead of estimating.</source>
        <translation>Gyroskop-Offset aus Ruhephasen, Beschleunigungs-Offset und -Skalierung aus mindestens sechs statischen Lagen (jede Achse nach oben und nach unten), Hard/Soft-Iron des Magnetometers aus einer Ellipsoidanpassung und eine Sättigungsprüfung. Schreibt den kalibrierten Datenstrom und die Kalibriertabelle (&lt;output&gt;-calibration); mit einer Kalibriertabelle als zweiter Eingabe wird diese angewandt statt geschätzt.</translation>
    </message>
    <message>
        <source>Estimate the gyroscope offset from rest periods (auto: when there is rest).</source>
        <translation>Gyroskop-Offset aus Ruhephasen schätzen (auto: wenn es Ruhe gibt).</translation>
    </message>
    <message>
        <source>Estimate accelerometer offset/scale (auto: when ≥ 6 static positions cover ±g on each axis).</source>
        <translation>Beschleunigungs-Offset/-Skalierung schätzen (auto: wenn ≥ 6 statische Lagen ±g auf jeder Achse abdecken).</translation>
    </message>
    <message>
        <source>Fit magnetometer hard/soft iron (auto: when mag columns exist and the fit succeeds).</source>
        <translation>Hard/Soft-Iron des Magnetometers anpassen (auto: wenn Magnetometerspalten existieren und die Anpassung gelingt).</translation>
    </message>
    <message>
        <source>Shortest static position.</source>
        <translation>Kürzeste statische Lage.</translation>
    </message>
    <message>
        <source>Local gravity.</source>
        <translation>Lokale Schwerebeschleunigung.</translation>
    </message>
    <message>
        <source>Accelerometer range for the saturation check (0: detect clipping).</source>
        <translation>Messbereich des Beschleunigungsmessers für die Sättigungsprüfung (0: Abschneiden erkennen).</translation>
    </message>
    <message>
        <source>Gyroscope range for the saturation check (0: detect clipping).</source>
        <translation>Messbereich des Gyroskops für die Sättigungsprüfung (0: Abschneiden erkennen).</translation>
    </message>
    <message>
        <source>Smallest plausible magnetic field after calibration (median |m|); default: the minimum geomagnetic total intensity at the Earth&apos;s surface (World Magnetic Model).</source>
        <translation>Kleinstes plausibles Magnetfeld nach der Kalibrierung (Median von |m|); Vorgabe: die minimale geomagnetische Totalintensität an der Erdoberfläche (World Magnetic Model).</translation>
    </message>
    <message>
        <source>Largest plausible magnetic field after calibration; default: the maximum geomagnetic total intensity at the Earth&apos;s surface (World Magnetic Model).</source>
        <translation>Größtes plausibles Magnetfeld nach der Kalibrierung; Vorgabe: die maximale geomagnetische Totalintensität an der Erdoberfläche (World Magnetic Model).</translation>
    </message>
    <message>
        <source>Largest plausible deviation of |a| at rest from gravity after calibration, as a fraction of gravity; default: the ±3 % factory tolerance of MEMS accelerometers.</source>
        <translation>Größte plausible Abweichung von |a| in Ruhe von der Schwerebeschleunigung nach der Kalibrierung, als Anteil der Schwerebeschleunigung; Vorgabe: die Werkstoleranz von ±3 % bei MEMS-Beschleunigungsmessern.</translation>
    </message>
    <message>
        <source>Largest plausible |scale − 1| of a fitted accelerometer axis (datasheet tolerances, rounded up).</source>
        <translation>Größtes plausibles |scale − 1| einer angepassten Achse des Beschleunigungsmessers (Datenblatttoleranzen, aufgerundet).</translation>
    </message>
    <message>
        <source>Store a calibration that fails the plausibility checks, flagged in the attribute &apos;implausible&apos; of both outputs, instead of refusing it.</source>
        <translation>Eine Kalibrierung, die die Plausibilitätsprüfungen nicht besteht, speichern (im Attribut „implausible“ beider Ausgaben markiert), statt sie abzulehnen.</translation>
    </message>
    <message>
        <source>IMU stream to calibrate.</source>
        <translation>Zu kalibrierender IMU-Datenstrom.</translation>
    </message>
    <message>
        <source>Optional calibration table to apply instead of estimating one.</source>
        <translation>Optionale Kalibriertabelle, die angewandt wird, statt eine zu schätzen.</translation>
    </message>
    <message>
        <source>Calibrated IMU stream.</source>
        <translation>Kalibrierter IMU-Datenstrom.</translation>
    </message>
    <message>
        <source>Calibration parameters: rows gyr_offset, acc_offset, acc_scale, mag_hard_iron, mag_soft_iron_0..2.</source>
        <translation>Kalibrierparameter: Zeilen gyr_offset, acc_offset, acc_scale, mag_hard_iron, mag_soft_iron_0..2.</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::JointAnglesProcessor</name>
    <message>
        <source>Joint angles</source>
        <translation>Gelenkwinkel</translation>
    </message>
    <message>
        <source>Knee, hip, ankle or trunk angles from the orientations of a proximal and a distal sensor (ISB recommendations, Grood &amp; Suntay joint coordinate system = Z-X-Y Cardan angles of the relative segment rotation): flexion, abduction and internal rotation, positive on both sides (the left side is mirrored). The sensors&apos; mounts (segment to sensor rotations) come from parameters or a segment-calibration table. Independent 6D headings are aligned over the first seconds, where the segments must face the same way (e.g. standing).</source>
        <translation>Knie-, Hüft-, Sprung- oder Rumpfwinkel aus den Orientierungen eines proximalen und eines distalen Sensors (ISB-Empfehlungen, Gelenkkoordinatensystem nach Grood &amp; Suntay = Z-X-Y-Cardanwinkel der relativen Segmentrotation): Flexion, Abduktion und Innenrotation, auf beiden Seiten positiv (die linke Seite wird gespiegelt). Die Montagen der Sensoren (Rotationen Segment → Sensor) kommen aus Parametern oder einer segment-calibration-Tabelle. Unabhängige 6D-Richtungen werden über die ersten Sekunden ausgerichtet, in denen die Segmente in dieselbe Richtung zeigen müssen (z. B. im Stehen).</translation>
    </message>
    <message>
        <source>knee (thigh → shank), hip (pelvis → thigh), ankle (shank → foot) or trunk (pelvis → thorax).</source>
        <translation>knee (Oberschenkel → Unterschenkel), hip (Becken → Oberschenkel), ankle (Unterschenkel → Fuß) oder trunk (Becken → Thorax).</translation>
    </message>
    <message>
        <source>Body side; the left side is mirrored so that positive abduction and internal rotation mean the same on both sides.</source>
        <translation>Körperseite; die linke Seite wird gespiegelt, damit positive Abduktion und Innenrotation auf beiden Seiten dasselbe bedeuten.</translation>
    </message>
    <message>
        <source>Proximal segment frame in the sensor frame as a quaternion w,x,y,z (maps segment to sensor coordinates; ISB segment axes X anterior, Y superior, Z right).</source>
        <translation>Proximales Segmentsystem im Sensorsystem als Quaternion w,x,y,z (bildet Segment- auf Sensorkoordinaten ab; ISB-Segmentachsen X anterior, Y superior, Z rechts).</translation>
    </message>
    <message>
        <source>Distal segment frame in the sensor frame (w,x,y,z).</source>
        <translation>Distales Segmentsystem im Sensorsystem (w,x,y,z).</translation>
    </message>
    <message>
        <source>align-start: rotate the distal sensor&apos;s earth frame about the vertical so that both segments face the same way at the start (needed for 6D orientations); none: use the headings as they are (9D or optical).</source>
        <translation>align-start: das Erdsystem des distalen Sensors um die Vertikale drehen, sodass beide Segmente zu Beginn in dieselbe Richtung zeigen (nötig für 6D-Orientierungen); none: die Richtungen unverändert verwenden (9D oder optisch).</translation>
    </message>
    <message>
        <source>Length of the start window for heading alignment.</source>
        <translation>Länge des Startfensters für die Richtungsausrichtung.</translation>
    </message>
    <message>
        <source>Orientation of the proximal segment&apos;s sensor (qw, qx, qy, qz).</source>
        <translation>Orientierung des Sensors des proximalen Segments (qw, qx, qy, qz).</translation>
    </message>
    <message>
        <source>Orientation of the distal segment&apos;s sensor (qw, qx, qy, qz).</source>
        <translation>Orientierung des Sensors des distalen Segments (qw, qx, qy, qz).</translation>
    </message>
    <message>
        <source>Segment-calibration table (segment, qw..qz) with rows for both segments of the joint.</source>
        <translation>Segment-calibration-Tabelle (segment, qw..qz) mit Zeilen für beide Segmente des Gelenks.</translation>
    </message>
    <message>
        <source>flexion, abduction, rotation (rad), long_axis_angle, proximal_inclination, distal_inclination (rad).</source>
        <translation>flexion, abduction, rotation (rad), long_axis_angle, proximal_inclination, distal_inclination (rad).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::OrientationProcessor</name>
    <message>
        <source>Orientation (IMU)</source>
        <translation>Orientierung (IMU)</translation>
    </message>
    <message>
        <source>Sensor-to-earth orientation (ENU, scalar-first quaternions) from gyroscope + accelerometer (6D) or + magnetometer (9D), one row per input sample, with gyroscope bias estimate and rest / magnetic disturbance flags. Default: a VQF-class filter (Laidig &amp; Seel 2023) with bias estimation at rest and in motion, accelerometer correction in an almost inertial frame and heading-only magnetometer correction with disturbance rejection. Baselines: strapdown, madgwick, mahony, kalman (Kim et al. 2023).</source>
        <translation>Orientierung Sensor → Erde (ENU, Quaternionen mit Skalar zuerst) aus Gyroskop + Beschleunigungsmesser (6D) oder + Magnetometer (9D), eine Zeile je Eingabe-Abtastwert, mit geschätztem Gyroskop-Bias sowie Ruhe- und Magnetstörungs-Flags. Vorgabe: ein Filter der VQF-Klasse (Laidig &amp; Seel 2023) mit Bias-Schätzung in Ruhe und in Bewegung, Beschleunigungskorrektur in einem nahezu inertialen System und reiner Richtungskorrektur durch das Magnetometer mit Störungsunterdrückung. Vergleichsverfahren: strapdown, madgwick, mahony, kalman (Kim et al. 2023).</translation>
    </message>
    <message>
        <source>6d: gyroscope + accelerometer (heading drifts freely); 9d: also magnetometer; auto: 9d when the stream has mag_x..z.</source>
        <translation>6d: Gyroskop + Beschleunigungsmesser (die Richtung driftet frei); 9d: zusätzlich Magnetometer; auto: 9d, wenn der Datenstrom mag_x..z hat.</translation>
    </message>
    <message>
        <source>vqf (default, recommended), or a baseline for comparison: strapdown, madgwick, mahony, kalman.</source>
        <translation>vqf (Vorgabe, empfohlen) oder ein Vergleichsverfahren: strapdown, madgwick, mahony, kalman.</translation>
    </message>
    <message>
        <source>vqf: time constant of the accelerometer (inclination) correction.</source>
        <translation>vqf: Zeitkonstante der Beschleunigungskorrektur (Neigung).</translation>
    </message>
    <message>
        <source>vqf: time constant of the magnetometer (heading) correction.</source>
        <translation>vqf: Zeitkonstante der Magnetometerkorrektur (Richtung).</translation>
    </message>
    <message>
        <source>vqf: estimate the gyroscope bias (at rest and in motion).</source>
        <translation>vqf: den Gyroskop-Bias schätzen (in Ruhe und in Bewegung).</translation>
    </message>
    <message>
        <source>vqf: detect and ride out magnetic disturbances.</source>
        <translation>vqf: magnetische Störungen erkennen und überbrücken.</translation>
    </message>
    <message>
        <source>vqf: rest detection threshold on the gyroscope deviation.</source>
        <translation>vqf: Schwelle der Ruheerkennung für die Gyroskopabweichung.</translation>
    </message>
    <message>
        <source>vqf: rest detection threshold on the accelerometer deviation.</source>
        <translation>vqf: Schwelle der Ruheerkennung für die Beschleunigungsabweichung.</translation>
    </message>
    <message>
        <source>vqf: accelerometer measuring range; samples clipped at it do not correct the inclination (0 = unknown).</source>
        <translation>vqf: Messbereich des Beschleunigungsmessers; daran abgeschnittene Abtastwerte korrigieren die Neigung nicht (0 = unbekannt).</translation>
    </message>
    <message>
        <source>vqf: estimate from the whole recording (forward-backward bias smoothing, zero-phase inclination, heading of both passes; offline VQF, Laidig &amp; Seel 2023) instead of sample by sample. Same outputs.</source>
        <translation>vqf: aus der ganzen Aufnahme schätzen (Vorwärts-Rückwärts-Glättung des Bias, nullphasige Neigung, Richtung aus beiden Durchgängen; Offline-VQF, Laidig &amp; Seel 2023) statt Abtastwert für Abtastwert. Dieselben Ausgaben.</translation>
    </message>
    <message>
        <source>madgwick: gain.</source>
        <translation>madgwick: Verstärkung.</translation>
    </message>
    <message>
        <source>mahony: proportional gain.</source>
        <translation>mahony: Proportionalverstärkung.</translation>
    </message>
    <message>
        <source>mahony: integral gain.</source>
        <translation>mahony: Integralverstärkung.</translation>
    </message>
    <message>
        <source>IMU stream: acc_x..z (m/s^2), gyr_x..z (rad/s)[, mag_x..z (uT)] in the sensor frame.</source>
        <translation>IMU-Datenstrom: acc_x..z (m/s^2), gyr_x..z (rad/s)[, mag_x..z (uT)] im Sensorsystem.</translation>
    </message>
    <message>
        <source>qw, qx, qy, qz (sensor to ENU), bias_x..z (rad/s), rest and mag_disturbed flags (0/1).</source>
        <translation>qw, qx, qy, qz (Sensor → ENU), bias_x..z (rad/s), Flags rest und mag_disturbed (0/1).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::SegmentCalibrationProcessor</name>
    <message>
        <source>Segment calibration (functional)</source>
        <translation>Segmentkalibrierung (funktionell)</translation>
    </message>
    <message>
        <source>Sensor-to-segment mounts from a functional calibration: standing upright still (gravity gives the superior axis) and slow squats (the principal axis of the angular velocity gives the medio-lateral axis), combined by cross products. Writes a segment-calibration table (segment, qw..qz) for joint-angles.</source>
        <translation>Sensor-Segment-Montagen aus einer funktionellen Kalibrierung: ruhiges aufrechtes Stehen (die Schwerkraft liefert die superiore Achse) und langsame Kniebeugen (die Hauptachse der Winkelgeschwindigkeit liefert die medio-laterale Achse), über Kreuzprodukte kombiniert. Schreibt eine segment-calibration-Tabelle (segment, qw..qz) für joint-angles.</translation>
    </message>
    <message>
        <source>Segment of each input IMU, in input order (thigh, shank, pelvis or thorax).</source>
        <translation>Segment jeder Eingabe-IMU in der Reihenfolge der Eingaben (thigh, shank, pelvis oder thorax).</translation>
    </message>
    <message>
        <source>Start of the upright standing window.</source>
        <translation>Beginn des Fensters für aufrechtes Stehen.</translation>
    </message>
    <message>
        <source>End of the upright standing window.</source>
        <translation>Ende des Fensters für aufrechtes Stehen.</translation>
    </message>
    <message>
        <source>Start of the squats.</source>
        <translation>Beginn der Kniebeugen.</translation>
    </message>
    <message>
        <source>End of the squats.</source>
        <translation>Ende der Kniebeugen.</translation>
    </message>
    <message>
        <source>IMU of the first segment (acc, gyr).</source>
        <translation>IMU des ersten Segments (acc, gyr).</translation>
    </message>
    <message>
        <source>IMU of the second segment.</source>
        <translation>IMU des zweiten Segments.</translation>
    </message>
    <message>
        <source>IMU of the third segment.</source>
        <translation>IMU des dritten Segments.</translation>
    </message>
    <message>
        <source>segment, qw, qx, qy, qz (segment to sensor), axis_share, orthogonality (rad).</source>
        <translation>segment, qw, qx, qy, qz (Segment → Sensor), axis_share, orthogonality (rad).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::SimulateBodyProcessor</name>
    <message>
        <source>Simulate body IMUs</source>
        <translation>Körper-IMUs simulieren</translation>
    </message>
    <message>
        <source>Eight IMUs (sacrum, sternum, thighs, shanks, feet) with known, misaligned mounts off the joint axes: upright standing and squats for calibration, then walking or an alpine skiing run (turns 27 m apart at 20 m/s on a 26° slope), with gyroscope bias, slow drift, noise, scale, g-sensitivity, vibration and impacts. The sacrum IMU is at &lt;output&gt;, the others at &lt;output&gt;-&lt;segment&gt;; truth: segment orientations at &lt;output&gt;-segments, joint-centre positions at &lt;output&gt;-joint-centres, reference angles at &lt;output&gt;-&lt;joint&gt;-reference, the true mounts per side at &lt;output&gt;-right-mounts / &lt;output&gt;-left-mounts and sensor-to-joint vectors at &lt;output&gt;-joint-vectors.</source>
        <translation>Acht IMUs (Kreuzbein, Brustbein, Oberschenkel, Unterschenkel, Füße) mit bekannten, verdrehten Montagen abseits der Gelenkachsen: aufrechtes Stehen und Kniebeugen zur Kalibrierung, dann Gehen oder eine Alpinfahrt (Schwünge 27 m auseinander bei 20 m/s auf einem 26°-Hang), mit Gyroskop-Bias, langsamer Drift, Rauschen, Skalierung, g-Empfindlichkeit, Vibration und Stößen. Die Kreuzbein-IMU liegt unter &lt;output&gt;, die anderen unter &lt;output&gt;-&lt;segment&gt;; Referenz: Segmentorientierungen unter &lt;output&gt;-segments, Gelenkzentrumspositionen unter &lt;output&gt;-joint-centres, Referenzwinkel unter &lt;output&gt;-&lt;joint&gt;-reference, die wahren Montagen je Seite unter &lt;output&gt;-right-mounts / &lt;output&gt;-left-mounts und Sensor-Gelenk-Vektoren unter &lt;output&gt;-joint-vectors.</translation>
    </message>
    <message>
        <source>Random seed.</source>
        <translation>Zufallsstartwert.</translation>
    </message>
    <message>
        <source>Movement after the calibration block.</source>
        <translation>Bewegung nach dem Kalibrierblock.</translation>
    </message>
    <message>
        <source>IMU sampling rate.</source>
        <translation>Abtastrate der IMU.</translation>
    </message>
    <message>
        <source>Length of the walking or skiing phase (including the speed ramps).</source>
        <translation>Länge der Geh- oder Skiphase (einschließlich der Geschwindigkeitsrampen).</translation>
    </message>
    <message>
        <source>Number of calibration squats.</source>
        <translation>Anzahl der Kalibrier-Kniebeugen.</translation>
    </message>
    <message>
        <source>Largest constant gyroscope bias per axis (drawn uniformly).</source>
        <translation>Größter konstanter Gyroskop-Bias je Achse (gleichverteilt gezogen).</translation>
    </message>
    <message>
        <source>Slow gyroscope bias change during the motion (norm; ≈ 0.15°/s on snow, Fasel 2017 ch. 5).</source>
        <translation>Langsame Änderung des Gyroskop-Bias während der Bewegung (Norm; ≈ 0,15°/s auf Schnee, Fasel 2017 Kap. 5).</translation>
    </message>
    <message>
        <source>Gyroscope white noise per sample (standard deviation).</source>
        <translation>Weißes Rauschen des Gyroskops je Abtastwert (Standardabweichung).</translation>
    </message>
    <message>
        <source>Accelerometer white noise per sample (standard deviation).</source>
        <translation>Weißes Rauschen des Beschleunigungsmessers je Abtastwert (Standardabweichung).</translation>
    </message>
    <message>
        <source>Skiing: 15–30 Hz vibration amplitude at the feet (damped up the body).</source>
        <translation>Skifahren: Amplitude der 15–30-Hz-Vibration an den Füßen (den Körper hinauf gedämpft).</translation>
    </message>
    <message>
        <source>Skiing: mean rate of 10 ms impacts.</source>
        <translation>Skifahren: mittlere Rate von 10-ms-Stößen.</translation>
    </message>
    <message>
        <source>Sacrum IMU: acc_x..z, gyr_x..z.</source>
        <translation>Kreuzbein-IMU: acc_x..z, gyr_x..z.</translation>
    </message>
    <message>
        <source>IMU of this segment.</source>
        <translation>IMU dieses Segments.</translation>
    </message>
    <message>
        <source>True segment orientations &lt;segment&gt;_qw..qz (segment to ENU).</source>
        <translation>Wahre Segmentorientierungen &lt;segment&gt;_qw..qz (Segment → ENU).</translation>
    </message>
    <message>
        <source>True joint-centre positions &lt;joint&gt;_x..z (m, ENU).</source>
        <translation>Wahre Gelenkzentrumspositionen &lt;joint&gt;_x..z (m, ENU).</translation>
    </message>
    <message>
        <source>True joint angles (rad).</source>
        <translation>Wahre Gelenkwinkel (rad).</translation>
    </message>
    <message>
        <source>True mounts of pelvis, thorax and the right leg (segment, qw..qz).</source>
        <translation>Wahre Montagen von Becken, Thorax und rechtem Bein (segment, qw..qz).</translation>
    </message>
    <message>
        <source>True mounts of pelvis, thorax and the left leg.</source>
        <translation>Wahre Montagen von Becken, Thorax und linkem Bein.</translation>
    </message>
    <message>
        <source>True sensor-to-joint vectors (joint, proximal, distal, rp_x..z, rd_x..z in m).</source>
        <translation>Wahre Sensor-Gelenk-Vektoren (joint, proximal, distal, rp_x..z, rd_x..z in m).</translation>
    </message>
    <message>
        <source>Calibration trunk rotations after the squats (0 = none; the protocol has 3).</source>
        <translation>Kalibrier-Rumpfrotationen nach den Kniebeugen (0 = keine; das Protokoll hat 3).</translation>
    </message>
    <message>
        <source>Calibration hip ab/adductions per leg after them (0 = none; the protocol has 3).</source>
        <translation>Kalibrier-Hüft-Ab-/Adduktionen je Bein danach (0 = keine; das Protokoll hat 3).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::SimulateImuGnssProcessor</name>
    <message>
        <source>Simulate IMU and GNSS</source>
        <translation>IMU und GNSS simulieren</translation>
    </message>
    <message>
        <source>Simulated football session with known truth: sprints from standstill, decelerations, turns and jogging. IMU (acc, gyr, mag) with bias, noise, scale errors and saturation at &lt;output&gt;; GNSS (local ENU x, y, z, vx, vy, vz) with white and slowly correlated errors at &lt;output&gt;-gnss; the truth at &lt;output&gt;-truth.</source>
        <translation>Simulierte Fußballeinheit mit bekannter Referenz: Sprints aus dem Stand, Abbremsungen, Richtungswechsel und Traben. IMU (acc, gyr, mag) mit Bias, Rauschen, Skalierungsfehlern und Sättigung unter &lt;output&gt;; GNSS (lokal ENU x, y, z, vx, vy, vz) mit weißen und langsam korrelierten Fehlern unter &lt;output&gt;-gnss; die Referenz unter &lt;output&gt;-truth.</translation>
    </message>
    <message>
        <source>Random seed.</source>
        <translation>Zufallsstartwert.</translation>
    </message>
    <message>
        <source>Length of the session.</source>
        <translation>Länge der Einheit.</translation>
    </message>
    <message>
        <source>IMU sampling rate.</source>
        <translation>Abtastrate der IMU.</translation>
    </message>
    <message>
        <source>GNSS rate (the IMU rate must be a multiple of it).</source>
        <translation>GNSS-Rate (die IMU-Rate muss ein Vielfaches davon sein).</translation>
    </message>
    <message>
        <source>Horizontal RMS of the white GNSS position error.</source>
        <translation>Horizontaler RMS-Wert des weißen GNSS-Positionsfehlers.</translation>
    </message>
    <message>
        <source>Largest gyroscope bias per axis (drawn uniformly).</source>
        <translation>Größter Gyroskop-Bias je Achse (gleichverteilt gezogen).</translation>
    </message>
    <message>
        <source>acc_x..z, gyr_x..z, mag_x..z.</source>
        <translation>acc_x..z, gyr_x..z, mag_x..z.</translation>
    </message>
    <message>
        <source>x, y, z, vx, vy, vz (ENU).</source>
        <translation>x, y, z, vx, vy, vz (ENU).</translation>
    </message>
    <message>
        <source>True x, y, z, vx, vy, vz, qw..qz, speed, distance.</source>
        <translation>Wahre x, y, z, vx, vy, vz, qw..qz, speed, distance.</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::SimulateLimbProcessor</name>
    <message>
        <source>Simulate lower limb IMUs</source>
        <translation>Untere Extremität: IMUs simulieren</translation>
    </message>
    <message>
        <source>Pelvis, thigh and shank IMUs with known, non-trivial mounts during standing, walking along a curve and squats, with the true hip and knee angles (3 DOF). Thigh IMU at &lt;output&gt;, shank and pelvis IMUs at &lt;output&gt;-shank and &lt;output&gt;-pelvis, true segment orientations at &lt;output&gt;-segments, reference angles at &lt;output&gt;-knee-reference and &lt;output&gt;-hip-reference, the true mounts as a segment-calibration table at &lt;output&gt;-mounts.</source>
        <translation>IMUs an Becken, Oberschenkel und Unterschenkel mit bekannten, nicht trivialen Montagen beim Stehen, beim Gehen entlang einer Kurve und bei Kniebeugen, mit den wahren Hüft- und Kniewinkeln (3 Freiheitsgrade). Oberschenkel-IMU unter &lt;output&gt;, Unterschenkel- und Becken-IMU unter &lt;output&gt;-shank und &lt;output&gt;-pelvis, wahre Segmentorientierungen unter &lt;output&gt;-segments, Referenzwinkel unter &lt;output&gt;-knee-reference und &lt;output&gt;-hip-reference, die wahren Montagen als segment-calibration-Tabelle unter &lt;output&gt;-mounts.</translation>
    </message>
    <message>
        <source>Random seed.</source>
        <translation>Zufallsstartwert.</translation>
    </message>
    <message>
        <source>Which leg carries the thigh and shank sensors.</source>
        <translation>Welches Bein die Oberschenkel- und Unterschenkelsensoren trägt.</translation>
    </message>
    <message>
        <source>IMU sampling rate.</source>
        <translation>Abtastrate der IMU.</translation>
    </message>
    <message>
        <source>Length of the walking phase.</source>
        <translation>Länge der Gehphase.</translation>
    </message>
    <message>
        <source>Number of squats after walking.</source>
        <translation>Anzahl der Kniebeugen nach dem Gehen.</translation>
    </message>
    <message>
        <source>Largest gyroscope bias per axis (drawn uniformly).</source>
        <translation>Größter Gyroskop-Bias je Achse (gleichverteilt gezogen).</translation>
    </message>
    <message>
        <source>Gyroscope white noise per sample (standard deviation).</source>
        <translation>Weißes Rauschen des Gyroskops je Abtastwert (Standardabweichung).</translation>
    </message>
    <message>
        <source>Accelerometer white noise per sample (standard deviation).</source>
        <translation>Weißes Rauschen des Beschleunigungsmessers je Abtastwert (Standardabweichung).</translation>
    </message>
    <message>
        <source>Thigh IMU: acc_x..z, gyr_x..z.</source>
        <translation>Oberschenkel-IMU: acc_x..z, gyr_x..z.</translation>
    </message>
    <message>
        <source>Shank IMU.</source>
        <translation>Unterschenkel-IMU.</translation>
    </message>
    <message>
        <source>Pelvis IMU.</source>
        <translation>Becken-IMU.</translation>
    </message>
    <message>
        <source>True segment orientations pelvis_qw..qz, thigh_qw..qz, shank_qw..qz (segment to ENU).</source>
        <translation>Wahre Segmentorientierungen pelvis_qw..qz, thigh_qw..qz, shank_qw..qz (Segment → ENU).</translation>
    </message>
    <message>
        <source>True knee angles (rad).</source>
        <translation>Wahre Kniewinkel (rad).</translation>
    </message>
    <message>
        <source>True hip angles (rad).</source>
        <translation>Wahre Hüftwinkel (rad).</translation>
    </message>
    <message>
        <source>True mounts (segment, qw..qz).</source>
        <translation>Wahre Montagen (segment, qw..qz).</translation>
    </message>
</context>
<context>
    <name>athlos::inertial::VelocityResetProcessor</name>
    <message>
        <source>Velocity resets (foot or ski sensor)</source>
        <translation>Geschwindigkeits-Resets (Fuß- oder Skisensor)</translation>
    </message>
    <message>
        <source>Velocity and position of a foot- or ski-mounted sensor in the earth frame (Fasel 2017 ch. 2–4): zero-velocity phases found by gyroscope and accelerometer energy (the foot&apos;s stance; for cross-country skiing the thrust, where the ski stands still on the snow, refined by speed &lt; 0.1 m/s and inertial acceleration &lt; 1 m/s²), the inclination reset at each phase and spread by SLERP, gravity removed, the acceleration integrated, the velocity set to zero in each phase and the linear drift between phases removed. Inputs: orientation and IMU of the same sensor. Outputs: x, y, z, vx, vy, vz (NaN before the first and after the last phase) and the phases as a table (&lt;output&gt;-zero-velocity).</source>
        <translation>Geschwindigkeit und Position eines am Fuß oder Ski montierten Sensors im Erdsystem (Fasel 2017 Kap. 2–4): Nullgeschwindigkeitsphasen über Gyroskop- und Beschleunigungsenergie gefunden (die Standphase des Fußes; beim Skilanglauf der Abstoß, in dem der Ski auf dem Schnee stillsteht, verfeinert über Geschwindigkeit &lt; 0,1 m/s und Inertialbeschleunigung &lt; 1 m/s²), die Neigung in jeder Phase zurückgesetzt und per SLERP verteilt, die Schwerkraft entfernt, die Beschleunigung integriert, die Geschwindigkeit in jeder Phase auf null gesetzt und die lineare Drift zwischen den Phasen entfernt. Eingänge: Orientierung und IMU desselben Sensors. Ausgänge: x, y, z, vx, vy, vz (NaN vor der ersten und nach der letzten Phase) und die Phasen als Tabelle (&lt;output&gt;-zero-velocity).</translation>
    </message>
    <message>
        <source>foot: stance (mean |ω| &lt; 2 rad/s and acceleration spread &lt; 1 m/s² over 0.1 s, as measured on gaitmap&apos;s real walk); xc-ski: the thrust phase of the diagonal stride (|ω| &lt; 0.2 rad/s, |‖a‖ − g| &lt; 1 m/s² over 0.04 s for ≥ 0.08 s, then refined by speed and acceleration, Fasel 2017 ch. 3 Table 3.1). The parameters below override the mode&apos;s values.</source>
        <translation>foot: Standphase (mittleres |ω| &lt; 2 rad/s und Streuung der Beschleunigung &lt; 1 m/s² über 0,1 s, gemessen am realen Gehen von gaitmap); xc-ski: die Abstoßphase des Diagonalschritts (|ω| &lt; 0,2 rad/s, |‖a‖ − g| &lt; 1 m/s² über 0,04 s für ≥ 0,08 s, dann über Geschwindigkeit und Beschleunigung verfeinert, Fasel 2017 Kap. 3 Tabelle 3.1). Die Parameter unten überschreiben die Werte des Modus.</translation>
    </message>
    <message>
        <source>Centred moving mean of the detector signals (mode).</source>
        <translation>Zentrierter gleitender Mittelwert der Detektorsignale (Modus).</translation>
    </message>
    <message>
        <source>Zero velocity: mean gyroscope norm below (mode).</source>
        <translation>Nullgeschwindigkeit: mittlere Gyroskopnorm unter (Modus).</translation>
    </message>
    <message>
        <source>Zero velocity: mean |‖a‖ − 9.81 m/s²| below, 0 = not used (mode).</source>
        <translation>Nullgeschwindigkeit: mittleres |‖a‖ − 9,81 m/s²| unter, 0 = nicht verwendet (Modus).</translation>
    </message>
    <message>
        <source>Zero velocity: spread of the acceleration vector over the window below, 0 = not used (mode; the accelerometer term of Skog et al. 2010&apos;s SHOE detector).</source>
        <translation>Nullgeschwindigkeit: Streuung des Beschleunigungsvektors über das Fenster unter, 0 = nicht verwendet (Modus; der Beschleunigungsterm des SHOE-Detektors von Skog et al. 2010).</translation>
    </message>
    <message>
        <source>Shortest zero-velocity phase (mode).</source>
        <translation>Kürzeste Nullgeschwindigkeitsphase (Modus).</translation>
    </message>
    <message>
        <source>Phases closer than this are merged (mode: 0.1 s foot, 0 xc-ski).</source>
        <translation>Näher beieinander liegende Phasen werden zusammengefasst (Modus: 0,1 s foot, 0 xc-ski).</translation>
    </message>
    <message>
        <source>Central share of each phase whose mean integrated velocity is the drift (Fasel 2017 ch. 4: the central 50 %).</source>
        <translation>Zentraler Anteil jeder Phase, dessen mittlere integrierte Geschwindigkeit die Drift ist (Fasel 2017 Kap. 4: die zentralen 50 %).</translation>
    </message>
    <message>
        <source>Reset the inclination at each phase from the accelerometer and spread it by SLERP (Fasel 2017 Eq. 2.7) before removing gravity.</source>
        <translation>Die Neigung in jeder Phase aus dem Beschleunigungsmesser zurücksetzen und per SLERP verteilen (Fasel 2017 Gl. 2.7), bevor die Schwerkraft entfernt wird.</translation>
    </message>
    <message>
        <source>Between phases, carry the input orientation of the previous phase by the gyroscope and spread the mismatch at the next (Fasel 2017 ch. 3: integration of the angular velocity between thrusts); an online filter&apos;s inclination is pulled by the accelerations in between.</source>
        <translation>Zwischen den Phasen die Eingangsorientierung der vorigen Phase mit dem Gyroskop fortführen und die Abweichung bei der nächsten verteilen (Fasel 2017 Kap. 3: Integration der Winkelgeschwindigkeit zwischen Abstößen); die Neigung eines Online-Filters wird von den Beschleunigungen dazwischen verzogen.</translation>
    </message>
    <message>
        <source>Gravity removed; empty = the mean accelerometer norm at the zero-velocity phases.</source>
        <translation>Entfernte Schwerkraft; leer = die mittlere Beschleunigungsnorm in den Nullgeschwindigkeitsphasen.</translation>
    </message>
    <message>
        <source>Grow each phase while the corrected speed and the inertial acceleration stay below zero_speed and zero_acc (Fasel 2017 ch. 3); on in xc-ski mode.</source>
        <translation>Jede Phase erweitern, solange die korrigierte Geschwindigkeit und die Inertialbeschleunigung unter zero_speed und zero_acc bleiben (Fasel 2017 Kap. 3); im Modus xc-ski an.</translation>
    </message>
    <message>
        <source>Refinement: speed of a still ski (0.1 m/s, Fasel 2017 ch. 3–4).</source>
        <translation>Verfeinerung: Geschwindigkeit eines stehenden Skis (0,1 m/s, Fasel 2017 Kap. 3–4).</translation>
    </message>
    <message>
        <source>Refinement: inertial acceleration of a still ski (Fasel 2017 Table 3.1).</source>
        <translation>Verfeinerung: Inertialbeschleunigung eines stehenden Skis (Fasel 2017 Tabelle 3.1).</translation>
    </message>
    <message>
        <source>Orientation (qw..qz, sensor → earth) of the foot or ski sensor, on the IMU&apos;s time axis.</source>
        <translation>Orientierung (qw..qz, Sensor → Erde) des Fuß- oder Skisensors auf der Zeitachse der IMU.</translation>
    </message>
    <message>
        <source>IMU stream (acc_x..z in m/s², gyr_x..z in rad/s) of the same sensor.</source>
        <translation>IMU-Stream (acc_x..z in m/s², gyr_x..z in rad/s) desselben Sensors.</translation>
    </message>
    <message>
        <source>Position x, y, z (m) and velocity vx, vy, vz (m/s) in the orientation&apos;s earth frame, origin at the first zero-velocity phase; zero_velocity 1 inside a phase.</source>
        <translation>Position x, y, z (m) und Geschwindigkeit vx, vy, vz (m/s) im Erdsystem der Orientierung, Ursprung in der ersten Nullgeschwindigkeitsphase; zero_velocity 1 innerhalb einer Phase.</translation>
    </message>
    <message>
        <source>One row per zero-velocity phase: start, end, duration (s), drift_x..z (m/s, the integrated velocity removed there), tilt (rad, the inclination reset).</source>
        <translation>Eine Zeile je Nullgeschwindigkeitsphase: start, end, duration (s), drift_x..z (m/s, die dort entfernte integrierte Geschwindigkeit), tilt (rad, der Neigungs-Reset).</translation>
    </message>
</context>
<context>
    <name>athlos::lps::LpsAlignProcessor</name>
    <message>
        <source>LPS frame alignment</source>
        <translation>LPS-Koordinatenausrichtung</translation>
    </message>
    <message>
        <source>Rotates and translates a beacon table so that venue marks (e.g. the finish line and a point down the home straight) land at the given coordinates.</source>
        <translation>Dreht und verschiebt eine Bakentabelle so, dass Geländemarken (z. B. die Ziellinie und ein Punkt auf der Zielgeraden) auf den angegebenen Koordinaten liegen.</translation>
    </message>
    <message>
        <source>Marks &apos;x,y,z&gt;X,Y,Z; …&apos;: LPS coordinates &gt; desired coordinates (m); or give a marks table as second input.</source>
        <translation>Marken „x,y,z&gt;X,Y,Z; …“: LPS-Koordinaten &gt; gewünschte Koordinaten (m); oder eine Markentabelle als zweite Eingabe angeben.</translation>
    </message>
    <message>
        <source>yaw: rotation about the vertical only (≥ 2 marks); full: 3D rotation (≥ 3 marks).</source>
        <translation>yaw: nur Drehung um die Vertikale (≥ 2 Marken); full: 3D-Rotation (≥ 3 Marken).</translation>
    </message>
    <message>
        <source>Beacon table to move.</source>
        <translation>Zu verschiebende Bakentabelle.</translation>
    </message>
    <message>
        <source>Optional table x, y, z, target_x, target_y, target_z (m), one row per mark.</source>
        <translation>Optionale Tabelle x, y, z, target_x, target_y, target_z (m), eine Zeile je Marke.</translation>
    </message>
    <message>
        <source>Moved beacon table; a &apos;ref&apos; row holds the moved reference node.</source>
        <translation>Verschobene Bakentabelle; eine Zeile „ref“ enthält den verschobenen Referenzknoten.</translation>
    </message>
</context>
<context>
    <name>athlos::lps::LpsCalibrationProcessor</name>
    <message>
        <source>LPS beacon calibration</source>
        <translation>LPS-Bakenkalibrierung</translation>
    </message>
    <message>
        <source>Automatic calibration of a TDoA LPS from a walk at constant height and rough initial beacon positions: outlier removal, ~200 well-spread fixes, joint least squares over beacons, tag positions and offsets (minimising nRMSR), multi-start when residuals stay high. The rotation about the reference node&apos;s vertical axis is not observable from TDoA: it is taken from the running track when the walk follows it (gauge=auto|track, thesis step 6 &quot;rotate the frame to venue marks&quot;) or from the initial guess.</source>
        <translation>Automatische Kalibrierung eines TDoA-LPS aus einem Gang in konstanter Höhe und groben Anfangspositionen der Baken: Ausreißerentfernung, ~200 gut verteilte Positionen, gemeinsame kleinste Quadrate über Baken, Tag-Positionen und Offsets (Minimierung von nRMSR), Mehrfachstart, wenn die Residuen hoch bleiben. Die Drehung um die Vertikalachse des Referenzknotens ist aus TDoA nicht beobachtbar: sie wird der Laufbahn entnommen, wenn der Gang ihr folgt (gauge=auto|track, Schritt 6 der Arbeit „das System an Geländemarken ausrichten“), oder der Anfangsschätzung.</translation>
    </message>
    <message>
        <source>Height of the tag during the walk in the LPS frame; absent = estimated (one unknown for the whole walk).</source>
        <translation>Höhe des Tags während des Gangs im LPS-System; fehlt sie, wird sie geschätzt (eine Unbekannte für den ganzen Gang).</translation>
    </message>
    <message>
        <source>Prior mean of the estimated walk height (hand-held tag).</source>
        <translation>A-priori-Mittelwert der geschätzten Ganghöhe (in der Hand gehaltener Tag).</translation>
    </message>
    <message>
        <source>Prior standard deviation of the estimated walk height.</source>
        <translation>A-priori-Standardabweichung der geschätzten Ganghöhe.</translation>
    </message>
    <message>
        <source>Fixes spread over the area used for the calibration (thesis: 200); 0 = all.</source>
        <translation>Über die Fläche verteilte Positionen für die Kalibrierung (Arbeit: 200); 0 = alle.</translation>
    </message>
    <message>
        <source>Outlier test on the residuals.</source>
        <translation>Ausreißertest auf den Residuen.</translation>
    </message>
    <message>
        <source>Significance of the Grubbs test.</source>
        <translation>Signifikanzniveau des Grubbs-Tests.</translation>
    </message>
    <message>
        <source>Horizontal uncertainty of the initial beacon positions (weak prior).</source>
        <translation>Horizontale Unsicherheit der Anfangspositionen der Baken (schwacher Prior).</translation>
    </message>
    <message>
        <source>Vertical uncertainty of the initial beacon positions (weak prior).</source>
        <translation>Vertikale Unsicherheit der Anfangspositionen der Baken (schwacher Prior).</translation>
    </message>
    <message>
        <source>Stop when nRMSR improves by less than this fraction per iteration (thesis: 0.01 %).</source>
        <translation>Anhalten, wenn sich nRMSR je Iteration um weniger als diesen Anteil verbessert (Arbeit: 0,01 %).</translation>
    </message>
    <message>
        <source>Starts from re-perturbed initial positions while nRMSR stays above restart_nrmsr.</source>
        <translation>Neustarts aus erneut gestörten Anfangspositionen, solange nRMSR über restart_nrmsr bleibt.</translation>
    </message>
    <message>
        <source>nRMSR above which the calibration restarts (about 3× the ranging noise).</source>
        <translation>nRMSR, über dem die Kalibrierung neu startet (etwa das 3-Fache des Entfernungsrauschens).</translation>
    </message>
    <message>
        <source>Seed of the restart perturbations (reproducible).</source>
        <translation>Startwert der Neustart-Störungen (reproduzierbar).</translation>
    </message>
    <message>
        <source>Rotation about the reference node&apos;s vertical axis. auto: fit the walk to a line parallel to the track and use that rotation if the fit is tight, covers the lap and agrees with the guess, else the guess; guess: from the initial beacon table only; track: always from the track fit.</source>
        <translation>Drehung um die Vertikalachse des Referenzknotens. auto: den Gang an eine zur Laufbahn parallele Linie anpassen und diese Drehung verwenden, wenn die Anpassung eng ist, die Runde abdeckt und mit der Schätzung übereinstimmt, sonst die Schätzung; guess: nur aus der anfänglichen Bakentabelle; track: immer aus der Bahnanpassung.</translation>
    </message>
    <message>
        <source>Track geometry the walk follows: a name under the project&apos;s /geometry or a built-in (iaaf-400m, indoor-200m). Used by gauge=auto|track.</source>
        <translation>Bahngeometrie, der der Gang folgt: ein Name unter /geometry des Projekts oder eine eingebaute (iaaf-400m, indoor-200m). Verwendet von gauge=auto|track.</translation>
    </message>
    <message>
        <source>Track origin x in LPS coordinates (overrides the geometry&apos;s pose).</source>
        <translation>Ursprung x der Bahn in LPS-Koordinaten (überschreibt die Lage der Geometrie).</translation>
    </message>
    <message>
        <source>Track origin y in LPS coordinates.</source>
        <translation>Ursprung y der Bahn in LPS-Koordinaten.</translation>
    </message>
    <message>
        <source>Rotation of the track frame in LPS coordinates (counter-clockwise).</source>
        <translation>Drehung des Bahnsystems in LPS-Koordinaten (gegen den Uhrzeigersinn).</translation>
    </message>
    <message>
        <source>gauge=auto: largest RMS distance of the walk from its fitted track line.</source>
        <translation>gauge=auto: größter RMS-Abstand des Gangs von seiner angepassten Bahnlinie.</translation>
    </message>
    <message>
        <source>gauge=auto: horizontal error of the initial guess for the agreement test (the track rotation must agree with the guess within 3σ); absent = prior_sigma_xy.</source>
        <translation>gauge=auto: horizontaler Fehler der Anfangsschätzung für den Übereinstimmungstest (die Bahndrehung muss innerhalb 3σ mit der Schätzung übereinstimmen); fehlt er, gilt prior_sigma_xy.</translation>
    </message>
    <message>
        <source>Beacons too few, clustered or collinear for the walk&apos;s area (horizontal spread below 1 m or below 1/50 of the area&apos;s extent): refuse the calibration, or only report it (report attributes geometry, geometry_reason).</source>
        <translation>Baken zu wenige, zu dicht beieinander oder auf einer Linie für die Fläche des Gangs (horizontale Streuung unter 1 m oder unter 1/50 der Ausdehnung der Fläche): die Kalibrierung ablehnen oder es nur melden (Attribute geometry, geometry_reason im Bericht).</translation>
    </message>
    <message>
        <source>Widen the prior to the guess error the first start finds (σ̂ from the horizontal shifts) when it exceeds 1.5 × prior_sigma_xy, and restart around that solution; for guesses metres off (aerial image, GNSS).</source>
        <translation>Den Prior auf den Schätzfehler erweitern, den der erste Start findet (σ̂ aus den horizontalen Verschiebungen), wenn er 1,5 × prior_sigma_xy übersteigt, und um diese Lösung neu starten; für Schätzungen, die Meter daneben liegen (Luftbild, GNSS).</translation>
    </message>
    <message>
        <source>Height plausibility: beacons are mounted above the walking tag. A planar walk cannot tell a beacon from its reflection in the walk plane; reflections below are flipped back (else each reflection is tested on nRMSR).</source>
        <translation>Plausibilität der Höhe: Baken sind über dem gehenden Tag montiert. Ein ebener Gang kann eine Bake nicht von ihrem Spiegelbild in der Gangebene unterscheiden; Spiegelbilder darunter werden zurückgeklappt (sonst wird jedes Spiegelbild über nRMSR geprüft).</translation>
    </message>
    <message>
        <source>beacons_above_walk: least height of a beacon above the walk plane.</source>
        <translation>beacons_above_walk: Mindesthöhe einer Bake über der Gangebene.</translation>
    </message>
    <message>
        <source>gauge=auto|track: one extra start with the walk&apos;s tags on a line parallel to the track; it is taken when at least 80 % of its tags lie within 3 × track_sigma of the line (nRMSR alone does not see a wrong geometry).</source>
        <translation>gauge=auto|track: ein zusätzlicher Start mit den Tags des Gangs auf einer zur Bahn parallelen Linie; er wird genommen, wenn mindestens 80 % seiner Tags innerhalb 3 × track_sigma der Linie liegen (nRMSR allein erkennt eine falsche Geometrie nicht).</translation>
    </message>
    <message>
        <source>track_constraint: σ of the walk&apos;s lateral offset about its line.</source>
        <translation>track_constraint: σ des seitlichen Versatzes des Gangs um seine Linie.</translation>
    </message>
    <message>
        <source>Relative nRMSR change that stops the final least-squares pass (the beacon heights lie in a flat valley the 0.01 % rule stops in).</source>
        <translation>Relative nRMSR-Änderung, die den letzten Kleinste-Quadrate-Durchgang beendet (die Bakenhöhen liegen in einem flachen Tal, in dem die 0,01-%-Regel anhält).</translation>
    </message>
    <message>
        <source>gauge=auto: least share of the lap (10 m bins) the walk must visit; on an oval also both bends.</source>
        <translation>gauge=auto: kleinster Anteil der Runde (10-m-Abschnitte), den der Gang besuchen muss; auf einem Oval auch beide Kurven.</translation>
    </message>
    <message>
        <source>TDoA readings of the calibration walk (tag at constant height, whole area).</source>
        <translation>TDoA-Messungen des Kalibriergangs (Tag in konstanter Höhe, ganze Fläche).</translation>
    </message>
    <message>
        <source>Initial beacon positions (site plan, aerial image, GNSS), from any recording.</source>
        <translation>Anfangspositionen der Baken (Lageplan, Luftbild, GNSS), aus beliebiger Aufnahme.</translation>
    </message>
    <message>
        <source>Optional surveyed beacon table: adds nRMSR_ref and η to the report.</source>
        <translation>Optionale vermessene Bakentabelle: ergänzt nRMSR_ref und η im Bericht.</translation>
    </message>
    <message>
        <source>Calibrated beacon table id, x, y, z (m).</source>
        <translation>Kalibrierte Bakentabelle id, x, y, z (m).</translation>
    </message>
    <message>
        <source>Per beacon: rms_residual (m), readings, shift (m); attributes: nRMSR before/after, η, walk height.</source>
        <translation>Je Bake: rms_residual (m), readings, shift (m); Attribute: nRMSR vorher/nachher, η, Ganghöhe.</translation>
    </message>
</context>
<context>
    <name>athlos::lps::LpsPositioningProcessor</name>
    <message>
        <source>LPS positioning (TDoA, ranges)</source>
        <translation>LPS-Positionierung (TDoA, Entfernungen)</translation>
    </message>
    <message>
        <source>Tag positions and clock offsets from TDoA readings and a beacon table, one fix per instant (2D at tag_height or 3D), with beacon selection against NLOS: all, IRLS (bisquare, 2.5·MAD), largest-residual rejection or the field of view of the body-worn tag. Two-way ranges (lps-range): ToA fixes on epochs merged from the anchors&apos; own report times, with all beacons or IRLS.</source>
        <translation>Tag-Positionen und Uhrenoffsets aus TDoA-Messungen und einer Bakentabelle, eine Position je Zeitpunkt (2D auf tag_height oder 3D), mit Bakenauswahl gegen NLOS: alle, IRLS (Bisquare, 2,5·MAD), Verwerfen des größten Residuums oder das Sichtfeld des am Körper getragenen Tags. Zweiwege-Entfernungen (lps-range): ToA-Positionen auf Epochen, die aus den eigenen Meldezeiten der Anker zusammengeführt werden, mit allen Baken oder IRLS.</translation>
    </message>
    <message>
        <source>2d solves x, y at tag_height; 3d also z; auto = 3d only when the beacons&apos; height span is at least 30 % of their horizontal extent (else z is ill-conditioned).</source>
        <translation>2d löst x, y auf tag_height; 3d auch z; auto = 3d nur, wenn die Höhenspanne der Baken mindestens 30 % ihrer horizontalen Ausdehnung beträgt (sonst ist z schlecht konditioniert).</translation>
    </message>
    <message>
        <source>Tag height in the LPS frame for 2D fixes.</source>
        <translation>Höhe des Tags im LPS-System für 2D-Positionen.</translation>
    </message>
    <message>
        <source>Beacon selection method (thesis §3.2, Fig. 3.16): grubbs and kalman-gate drop readings whose TDoA changes abruptly (Grubbs test on each beacon&apos;s TDoA rate; a constant-velocity Kalman filter per beacon with a Mahalanobis gate) and solve with the rest; all-subsets weights readings by their residuals summed over NLOS hypotheses (Cong &amp; Zhuang); best-subset keeps the best-fitting 5 readings.</source>
        <translation>Methode der Bakenauswahl (Arbeit §3.2, Abb. 3.16): grubbs und kalman-gate verwerfen Messungen, deren TDoA sich sprunghaft ändert (Grubbs-Test auf der TDoA-Rate jeder Bake; ein Kalman-Filter mit konstanter Geschwindigkeit je Bake mit Mahalanobis-Tor) und lösen mit den übrigen; all-subsets gewichtet Messungen nach ihren über NLOS-Hypothesen summierten Residuen (Cong &amp; Zhuang); best-subset behält die 5 am besten passenden Messungen.</translation>
    </message>
    <message>
        <source>kalman-gate: squared Mahalanobis distance above which a reading is dropped.</source>
        <translation>kalman-gate: quadrierte Mahalanobis-Distanz, über der eine Messung verworfen wird.</translation>
    </message>
    <message>
        <source>grubbs: significance level of the test (thesis: 0.05).</source>
        <translation>grubbs: Signifikanzniveau des Tests (Arbeit: 0,05).</translation>
    </message>
    <message>
        <source>all-subsets: NLOS hypotheses with at most this many readings (0 = all 2^B; slow beyond 12 readings).</source>
        <translation>all-subsets: NLOS-Hypothesen mit höchstens so vielen Messungen (0 = alle 2^B; langsam über 12 Messungen).</translation>
    </message>
    <message>
        <source>Robust loss of the fix (solved with a ceres::Problem; slower).</source>
        <translation>Robuste Verlustfunktion der Position (gelöst mit einem ceres::Problem; langsamer).</translation>
    </message>
    <message>
        <source>Residual at which the robust loss leaves its quadratic part.</source>
        <translation>Residuum, ab dem die robuste Verlustfunktion ihren quadratischen Teil verlässt.</translation>
    </message>
    <message>
        <source>Fewest beacons per fix (thesis: 4; TDoA needs at least 4, 2D ranges 3).</source>
        <translation>Wenigste Baken je Position (Arbeit: 4; TDoA braucht mindestens 4, 2D-Entfernungen 3).</translation>
    </message>
    <message>
        <source>Ranges: one fix every this many seconds from each anchor&apos;s newest range.</source>
        <translation>Entfernungen: eine Position alle so viele Sekunden aus der neuesten Entfernung jedes Ankers.</translation>
    </message>
    <message>
        <source>Ranges: a range older than this at the epoch is left out (never extrapolated).</source>
        <translation>Entfernungen: eine zur Epoche ältere Entfernung wird weggelassen (nie extrapoliert).</translation>
    </message>
    <message>
        <source>IRLS: bisquare cut-off in units of 1.4826·MAD of the residuals.</source>
        <translation>IRLS: Bisquare-Grenze in Einheiten von 1,4826·MAD der Residuen.</translation>
    </message>
    <message>
        <source>largest-residual: stop rejecting when the mean |residual| is below this.</source>
        <translation>largest-residual: das Verwerfen beenden, wenn das mittlere |Residuum| darunter liegt.</translation>
    </message>
    <message>
        <source>field-of-view: κ of the rule G_t(φ) − L_fs + κ &gt; 0 (Eqn. 3.8).</source>
        <translation>field-of-view: κ der Regel G_t(φ) − L_fs + κ &gt; 0 (Gl. 3.8).</translation>
    </message>
    <message>
        <source>field-of-view: body-worn tag pattern as &apos;angle_deg:linear_gain,…&apos; (0° = forward; 0…180° is mirrored); empty = ((1+cos φ)/2)^6 with −30 dB behind.</source>
        <translation>field-of-view: Muster des am Körper getragenen Tags als „angle_deg:linear_gain,…“ (0° = vorn; 0…180° wird gespiegelt); leer = ((1+cos φ)/2)^6 mit −30 dB hinten.</translation>
    </message>
    <message>
        <source>field-of-view: carrier frequency for the free-space loss.</source>
        <translation>field-of-view: Trägerfrequenz für den Freiraumverlust.</translation>
    </message>
    <message>
        <source>field-of-view: afterwards reject gross outliers among the beacons in view (leave-one-out), and re-solve a fix more than 4 m from the median of the last five fixes with IRLS over all beacons.</source>
        <translation>field-of-view: danach grobe Ausreißer unter den sichtbaren Baken verwerfen (leave-one-out) und eine Position, die mehr als 4 m vom Median der letzten fünf Positionen abweicht, mit IRLS über alle Baken neu lösen.</translation>
    </message>
    <message>
        <source>field-of-view: body heading from the track geometry and running direction, from the orientation input (sensor x axis = forward) or from the direction of travel.</source>
        <translation>field-of-view: Körperrichtung aus der Bahngeometrie und der Laufrichtung, aus der Orientierungseingabe (Sensorachse x = vorn) oder aus der Bewegungsrichtung.</translation>
    </message>
    <message>
        <source>field-of-view, heading=track: project geometry name or built-in track; the LPS frame must be the track&apos;s (see lps-align).</source>
        <translation>field-of-view, heading=track: Geometriename im Projekt oder eingebaute Bahn; das LPS-System muss das der Bahn sein (siehe lps-align).</translation>
    </message>
    <message>
        <source>field-of-view, heading=track: running direction (athletics: counter-clockwise).</source>
        <translation>field-of-view, heading=track: Laufrichtung (Leichtathletik: gegen den Uhrzeigersinn).</translation>
    </message>
    <message>
        <source>TDoA readings t, beacon, dt (s), several rows per instant; or two-way ranges t, beacon, range (m).</source>
        <translation>TDoA-Messungen t, beacon, dt (s), mehrere Zeilen je Zeitpunkt; oder Zweiwege-Entfernungen t, beacon, range (m).</translation>
    </message>
    <message>
        <source>Beacon table id, x, y, z (m), from any recording; a row &apos;ref&apos; places the reference node.</source>
        <translation>Bakentabelle id, x, y, z (m), aus beliebiger Aufnahme; eine Zeile „ref“ platziert den Referenzknoten.</translation>
    </message>
    <message>
        <source>Optional orientation (qw, qx, qy, qz) for heading=orientation.</source>
        <translation>Optionale Orientierung (qw, qx, qy, qz) für heading=orientation.</translation>
    </message>
    <message>
        <source>t, x, y, z (m), offset (s), rms_residual (m), n_beacons, dop (dilution of precision) per fix.</source>
        <translation>t, x, y, z (m), offset (s), rms_residual (m), n_beacons, dop (Dilution of Precision) je Position.</translation>
    </message>
</context>
<context>
    <name>athlos::lps::SimulateLpsProcessor</name>
    <message>
        <source>Simulate LPS venue and recording</source>
        <translation>LPS-Gelände und -Aufnahme simulieren</translation>
    </message>
    <message>
        <source>Simulated TDoA venue around a 400 m track and a calibration walk or a run on it: 7 µs offset, 0.1 m noise, 1 % positive outliers of 20 m, optional body-shadowing NLOS; plus surveyed and perturbed beacon tables and the true trajectory.</source>
        <translation>Simuliertes TDoA-Gelände um eine 400-m-Bahn und ein Kalibriergang oder ein Lauf darauf: 7 µs Offset, 0,1 m Rauschen, 1 % positive Ausreißer von 20 m, optional NLOS durch Abschattung des Körpers; dazu vermessene und gestörte Bakentabellen und die wahre Trajektorie.</translation>
    </message>
    <message>
        <source>walk: calibration walk in lane 1 (1.4 m/s, 1 Hz, 1.0 m); run: a runner (6 m/s, 10 Hz, 1.2 m).</source>
        <translation>walk: Kalibriergang auf Bahn 1 (1,4 m/s, 1 Hz, 1,0 m); run: ein Läufer (6 m/s, 10 Hz, 1,2 m).</translation>
    </message>
    <message>
        <source>Seed of the measurement noise.</source>
        <translation>Startwert des Messrauschens.</translation>
    </message>
    <message>
        <source>Seed of the venue and the initial guess.</source>
        <translation>Startwert des Geländes und der Anfangsschätzung.</translation>
    </message>
    <message>
        <source>Number of beacons.</source>
        <translation>Anzahl der Baken.</translation>
    </message>
    <message>
        <source>Laps of the 400 m track.</source>
        <translation>Runden der 400-m-Bahn.</translation>
    </message>
    <message>
        <source>Lane whose running line is followed.</source>
        <translation>Bahn, deren Laufline gefolgt wird.</translation>
    </message>
    <message>
        <source>Speed; 0 = scenario default.</source>
        <translation>Geschwindigkeit; 0 = Vorgabe des Szenarios.</translation>
    </message>
    <message>
        <source>Fix rate; 0 = scenario default.</source>
        <translation>Positionsrate; 0 = Vorgabe des Szenarios.</translation>
    </message>
    <message>
        <source>Tag height; negative = scenario default (walk 1.0 m, run 1.2 m).</source>
        <translation>Höhe des Tags; negativ = Vorgabe des Szenarios (Gang 1,0 m, Lauf 1,2 m).</translation>
    </message>
    <message>
        <source>Time of the first instant.</source>
        <translation>Zeit des ersten Zeitpunkts.</translation>
    </message>
    <message>
        <source>Horizontal error of the initial guess (thesis Table 3.2).</source>
        <translation>Horizontaler Fehler der Anfangsschätzung (Arbeit Tabelle 3.2).</translation>
    </message>
    <message>
        <source>Vertical error of the initial guess.</source>
        <translation>Vertikaler Fehler der Anfangsschätzung.</translation>
    </message>
    <message>
        <source>TDoA noise σ as a distance (c·σ_t).</source>
        <translation>TDoA-Rauschen σ als Distanz (c·σ_t).</translation>
    </message>
    <message>
        <source>Share of readings that are outliers.</source>
        <translation>Anteil der Messungen, die Ausreißer sind.</translation>
    </message>
    <message>
        <source>Outlier σ as a distance (positive errors).</source>
        <translation>σ der Ausreißer als Distanz (positive Fehler).</translation>
    </message>
    <message>
        <source>Body-shadowing NLOS of a chest-worn tag (run scenario).</source>
        <translation>NLOS durch Körperabschattung eines an der Brust getragenen Tags (Szenario run).</translation>
    </message>
    <message>
        <source>Offset t_off common to all beacons.</source>
        <translation>Für alle Baken gemeinsamer Offset t_off.</translation>
    </message>
    <message>
        <source>TDoA readings t, beacon, dt (s).</source>
        <translation>TDoA-Messungen t, beacon, dt (s).</translation>
    </message>
    <message>
        <source>Surveyed beacon table.</source>
        <translation>Vermessene Bakentabelle.</translation>
    </message>
    <message>
        <source>Perturbed initial beacon table.</source>
        <translation>Gestörte anfängliche Bakentabelle.</translation>
    </message>
    <message>
        <source>True tag trajectory t, x, y, z (m).</source>
        <translation>Wahre Trajektorie des Tags t, x, y, z (m).</translation>
    </message>
</context>
<context>
    <name>athlos::metrics::SessionMetricsProcessor</name>
    <message>
        <source>Session metrics</source>
        <translation>Einheitskennzahlen</translation>
    </message>
    <message>
        <source>The coach&apos;s metrics per period (whole session, annotated halves or drills, consecutive windows): distance, maximum speed, distance per speed zone, high-speed running, sprints, accelerations and decelerations, peak distance over 1, 3 and 5 min, metabolic power and energy (di Prampero 2005, Osgnach 2010), PlayerLoad from an IMU and action counts from annotations. Raw positions are smoothed first by the robust Kalman smoother (noise estimated from the data), because raw positions overstate distance.</source>
        <translation>Die Kennzahlen des Trainers je Abschnitt (ganze Einheit, annotierte Halbzeiten oder Übungen, aufeinanderfolgende Fenster): Distanz, Höchstgeschwindigkeit, Distanz je Geschwindigkeitszone, Hochgeschwindigkeitslaufen, Sprints, Beschleunigungen und Abbremsungen, Spitzendistanz über 1, 3 und 5 min, metabolische Leistung und Energie (di Prampero 2005, Osgnach 2010), PlayerLoad aus einer IMU und Aktionszahlen aus Annotationen. Rohpositionen werden zuerst mit dem robusten Kalman-Glätter geglättet (Rauschen aus den Daten geschätzt), weil Rohpositionen die Distanz überschätzen.</translation>
    </message>
    <message>
        <source>auto: smooth raw fixes (lps-position, gnss) with the robust Kalman smoother and use a trajectory (position-filter output) as it is; none: raw positions, speed by central differences (overstates distance and speed; for comparison).</source>
        <translation>auto: Rohpositionen (lps-position, gnss) mit dem robusten Kalman-Glätter glätten und eine Trajektorie (Ausgabe von position-filter) unverändert verwenden; none: Rohpositionen, Geschwindigkeit durch zentrale Differenzen (überschätzt Distanz und Geschwindigkeit; zum Vergleich).</translation>
    </message>
    <message>
        <source>Motion model of the smoother: constant velocity (white-noise acceleration; its smoothed speed keeps the accelerations of team sports, docs/validation/session-metrics.md) or constant turn rate and acceleration.</source>
        <translation>Bewegungsmodell des Glätters: konstante Geschwindigkeit (Beschleunigung als weißes Rauschen; seine geglättete Geschwindigkeit erhält die Beschleunigungen der Mannschaftssportarten, docs/validation/session-metrics.md) oder konstante Drehrate und Beschleunigung.</translation>
    </message>
    <message>
        <source>Sampling rate of the smoothed motion the metrics are computed on.</source>
        <translation>Abtastrate der geglätteten Bewegung, auf der die Kennzahlen berechnet werden.</translation>
    </message>
    <message>
        <source>Outages longer than this are not bridged: no distance is counted across them.</source>
        <translation>Ausfälle, die länger dauern, werden nicht überbrückt: über sie wird keine Distanz gezählt.</translation>
    </message>
    <message>
        <source>The smoother&apos;s noise is estimated on this many evenly spread chunks of the recording (0 = on all of it).</source>
        <translation>Das Rauschen des Glätters wird auf so vielen gleichmäßig verteilten Abschnitten der Aufnahme geschätzt (0 = auf der ganzen).</translation>
    </message>
    <message>
        <source>Length of one chunk of the noise estimate.</source>
        <translation>Länge eines Abschnitts der Rauschschätzung.</translation>
    </message>
    <message>
        <source>Lower edges of the speed zones in km/h (Bradley et al. 2009; the vendors&apos; defaults); the last zone is open.</source>
        <translation>Untergrenzen der Geschwindigkeitszonen in km/h (Bradley et al. 2009; die Vorgaben der Hersteller); die letzte Zone ist offen.</translation>
    </message>
    <message>
        <source>High-speed running above this speed (19.8 km/h, Bradley et al. 2009).</source>
        <translation>Hochgeschwindigkeitslaufen über dieser Geschwindigkeit (19,8 km/h, Bradley et al. 2009).</translation>
    </message>
    <message>
        <source>Sprint entry speed (25.2 km/h, Bradley et al. 2009).</source>
        <translation>Eintrittsgeschwindigkeit eines Sprints (25,2 km/h, Bradley et al. 2009).</translation>
    </message>
    <message>
        <source>max_speed is the highest speed held at least this long, so that one noisy sample cannot set it (0 = the largest single sample).</source>
        <translation>max_speed ist die höchste Geschwindigkeit, die mindestens so lange gehalten wird, damit ein verrauschter Abtastwert sie nicht bestimmen kann (0 = der größte einzelne Abtastwert).</translation>
    </message>
    <message>
        <source>Minimum time above the sprint speed (1 s, Di Salvo et al. 2010).</source>
        <translation>Mindestzeit über der Sprintgeschwindigkeit (1 s, Di Salvo et al. 2010).</translation>
    </message>
    <message>
        <source>Acceleration and deceleration efforts at or beyond ± this (3 m/s², Akenhead et al. 2013).</source>
        <translation>Beschleunigungs- und Abbremsaktionen bei oder jenseits von ± diesem Wert (3 m/s², Akenhead et al. 2013).</translation>
    </message>
    <message>
        <source>Minimum duration of an acceleration or deceleration effort (0.5 s, Varley et al. 2012).</source>
        <translation>Mindestdauer einer Beschleunigungs- oder Abbremsaktion (0,5 s, Varley et al. 2012).</translation>
    </message>
    <message>
        <source>Peak distance over these window lengths (s).</source>
        <translation>Spitzendistanz über diese Fensterlängen (s).</translation>
    </message>
    <message>
        <source>Consecutive windows of this length as extra rows (0 = none).</source>
        <translation>Aufeinanderfolgende Fenster dieser Länge als zusätzliche Zeilen (0 = keine).</translation>
    </message>
    <message>
        <source>Annotation labels that are periods (halves, drills), comma-separated; auto: interval annotations whose label matches period_pattern. Other annotations are counted as actions.</source>
        <translation>Annotationsbezeichnungen, die Abschnitte sind (Halbzeiten, Übungen), durch Kommas getrennt; auto: Intervall-Annotationen, deren Bezeichnung zu period_pattern passt. Andere Annotationen werden als Aktionen gezählt.</translation>
    </message>
    <message>
        <source>Regular expression (case-insensitive) of period labels for periods=auto.</source>
        <translation>Regulärer Ausdruck (ohne Groß-/Kleinschreibung) für Abschnittsbezeichnungen bei periods=auto.</translation>
    </message>
    <message>
        <source>A track (a name under the project&apos;s /geometry or a built-in: iaaf-400m, indoor-200m): adds a row per lap and per split_distance, from the progress along the track. Empty: no track.</source>
        <translation>Eine Bahn (ein Name unter /geometry des Projekts oder eine eingebaute: iaaf-400m, indoor-200m): ergänzt eine Zeile je Runde und je split_distance, aus dem Fortschritt entlang der Bahn. Leer: keine Bahn.</translation>
    </message>
    <message>
        <source>Split length along lane 1&apos;s running line with a track (0 = laps only).</source>
        <translation>Zwischenzeitlänge entlang der Laufline von Bahn 1 bei einer Bahn (0 = nur Runden).</translation>
    </message>
    <message>
        <source>KT of the energy cost: 1.29 for grass (Osgnach et al. 2010), 1 for a track.</source>
        <translation>KT der Energiekosten: 1,29 für Rasen (Osgnach et al. 2010), 1 für eine Bahn.</translation>
    </message>
    <message>
        <source>High metabolic power distance above this power (20 W/kg, Osgnach et al. 2010).</source>
        <translation>Distanz mit hoher metabolischer Leistung über dieser Leistung (20 W/kg, Osgnach et al. 2010).</translation>
    </message>
    <message>
        <source>Positions t, x, y (m): LPS fixes, GNSS (x, y in the project&apos;s ENU frame) or a filtered trajectory.</source>
        <translation>Positionen t, x, y (m): LPS-Positionen, GNSS (x, y im ENU-System des Projekts) oder eine gefilterte Trajektorie.</translation>
    </message>
    <message>
        <source>Optional IMU (acc_x, acc_y, acc_z) for PlayerLoad.</source>
        <translation>Optionale IMU (acc_x, acc_y, acc_z) für PlayerLoad.</translation>
    </message>
    <message>
        <source>One row per period: period, start, end, duration, distance, max_speed, zone distances, hsr_distance, sprint/acceleration/deceleration counts, peak distances, metabolic energy and power, high-power distance, player_load, actions_&lt;label&gt;.</source>
        <translation>Eine Zeile je Abschnitt: period, start, end, duration, distance, max_speed, Zonendistanzen, hsr_distance, Anzahl der Sprints/Beschleunigungen/Abbremsungen, Spitzendistanzen, metabolische Energie und Leistung, Distanz mit hoher Leistung, player_load, actions_&lt;label&gt;.</translation>
    </message>
    <message>
        <source>The motion the metrics were computed on: x, y (m), speed (m/s), accel (m/s^2), valid.</source>
        <translation>Die Bewegung, auf der die Kennzahlen berechnet wurden: x, y (m), speed (m/s), accel (m/s^2), valid.</translation>
    </message>
</context>
<context>
    <name>athlos::positioning::AnchorGateAverageProcessor</name>
    <message>
        <source>Average gate positions over runs (GNSS-free)</source>
        <translation>Torpositionen über Läufe mitteln (ohne GNSS)</translation>
    </message>
    <message>
        <source>GNSS-free gate positions (Fasel thesis ch. 10): the gate estimates of several anchor-smoother runs, each aligned and scaled to the mean first and last gates, averaged gate by gate.</source>
        <translation>Torpositionen ohne GNSS (Arbeit von Fasel Kap. 10): die Torschätzungen mehrerer anchor-smoother-Läufe, jeweils auf das mittlere erste und letzte Tor ausgerichtet und skaliert, Tor für Tor gemittelt.</translation>
    </message>
    <message>
        <source>Crossings table of an anchor-smoother run.</source>
        <translation>Durchfahrtstabelle eines anchor-smoother-Laufs.</translation>
    </message>
    <message>
        <source>Averaged gates: id, east, north, up (m).</source>
        <translation>Gemittelte Tore: id, east, north, up (m).</translation>
    </message>
</context>
<context>
    <name>athlos::positioning::AnchorSmootherProcessor</name>
    <message>
        <source>Anchor-point smoother (gate magnets)</source>
        <translation>Ankerpunkt-Glätter (Tormagnete)</translation>
    </message>
    <message>
        <source>Sacrum trajectory from an IMU with magnetometer, its orientation and the gate positions (Fasel thesis ch. 9): gate crossings from magnetometer peaks (eq. 9.1), a 16-state extended Kalman smoother (constant acceleration, ZUPT at start and finish) with anchor updates at the gates in two passes (1 m, then 0.2 m), low-passed at 5 Hz.</source>
        <translation>Kreuzbeintrajektorie aus einer IMU mit Magnetometer, ihrer Orientierung und den Torpositionen (Arbeit von Fasel Kap. 9): Tordurchfahrten aus Magnetometerspitzen (Gl. 9.1), ein erweiterter Kalman-Glätter mit 16 Zuständen (konstante Beschleunigung, ZUPT an Start und Ziel) mit Anker-Updates an den Toren in zwei Durchgängen (1 m, dann 0,2 m), mit 5 Hz tiefpassgefiltert.</translation>
    </message>
    <message>
        <source>Gate detection: magnet field in units of the ambient field (eq. 9.1: 0.3 = 0.88 m; the thesis saw magnets up to 0.8 m).</source>
        <translation>Torerkennung: Magnetfeld in Einheiten des Umgebungsfelds (Gl. 9.1: 0,3 = 0,88 m; die Arbeit sah Magnete bis 0,8 m).</translation>
    </message>
    <message>
        <source>Shortest time between two gate crossings.</source>
        <translation>Kürzeste Zeit zwischen zwei Tordurchfahrten.</translation>
    </message>
    <message>
        <source>Sacrum position at the start as east,north,up (m) in the gates&apos; frame; empty = from the matched gates.</source>
        <translation>Kreuzbeinposition am Start als east,north,up (m) im System der Tore; leer = aus den zugeordneten Toren.</translation>
    </message>
    <message>
        <source>rest-aligned: re-integrate the gyroscope from the stream&apos;s start orientation with the bias of the start rest and remove the tilt drift found at the finish rest (thesis ch. 3-4, 9); stream: use the orientation stream as it is.</source>
        <translation>rest-aligned: das Gyroskop ab der Startorientierung des Datenstroms mit dem Bias der Startruhe neu integrieren und die bei der Zielruhe gefundene Neigungsdrift entfernen (Arbeit Kap. 3–4, 9); stream: den Orientierungsdatenstrom unverändert verwenden.</translation>
    </message>
    <message>
        <source>Smoother rate (the IMU is block-averaged onto it).</source>
        <translation>Rate des Glätters (die IMU wird blockweise darauf gemittelt).</translation>
    </message>
    <message>
        <source>Acceleration accuracy (thesis sec. 9.2.2: 1.5 m/s^2).</source>
        <translation>Genauigkeit der Beschleunigung (Arbeit Abschn. 9.2.2: 1,5 m/s^2).</translation>
    </message>
    <message>
        <source>Jerk noise floor of the constant-acceleration model; the measured acceleration change adds to it (thesis: larger noise in the turns).</source>
        <translation>Untergrenze des Rucks im Modell konstanter Beschleunigung; die gemessene Beschleunigungsänderung kommt hinzu (Arbeit: größeres Rauschen in den Schwüngen).</translation>
    </message>
    <message>
        <source>Random walk of the acceleration offset state.</source>
        <translation>Random Walk des Beschleunigungs-Offset-Zustands.</translation>
    </message>
    <message>
        <source>Anchor accuracy in the first pass (thesis: 1 m).</source>
        <translation>Genauigkeit der Anker im ersten Durchgang (Arbeit: 1 m).</translation>
    </message>
    <message>
        <source>Anchor accuracy in the second pass (thesis: 0.2 m).</source>
        <translation>Genauigkeit der Anker im zweiten Durchgang (Arbeit: 0,2 m).</translation>
    </message>
    <message>
        <source>Sacrum above the snow at a gate crossing (|d_m| of eqs. 9.2-9.5).</source>
        <translation>Kreuzbein über dem Schnee bei einer Tordurchfahrt (|d_m| aus Gl. 9.2–9.5).</translation>
    </message>
    <message>
        <source>Largest distance of a crossing from its expected gate.</source>
        <translation>Größter Abstand einer Durchfahrt von ihrem erwarteten Tor.</translation>
    </message>
    <message>
        <source>Zero-phase 2nd-order Butterworth on the output (thesis: 5 Hz); 0 = none.</source>
        <translation>Nullphasiger Butterworth 2. Ordnung auf der Ausgabe (Arbeit: 5 Hz); 0 = keiner.</translation>
    </message>
    <message>
        <source>Anchor passes (thesis: 2); 0 = ZUPT-only integration, for comparison.</source>
        <translation>Anker-Durchgänge (Arbeit: 2); 0 = Integration nur mit ZUPT, zum Vergleich.</translation>
    </message>
    <message>
        <source>Standing at start/finish: angular rate below this.</source>
        <translation>Stehen an Start/Ziel: Drehrate unter diesem Wert.</translation>
    </message>
    <message>
        <source>Standing at start/finish: gravity-free acceleration below this.</source>
        <translation>Stehen an Start/Ziel: schwerkraftfreie Beschleunigung unter diesem Wert.</translation>
    </message>
    <message>
        <source>Sacrum IMU with acc, gyr and mag.</source>
        <translation>Kreuzbein-IMU mit acc, gyr und mag.</translation>
    </message>
    <message>
        <source>Its orientation (processor orientation), one row per IMU sample.</source>
        <translation>Ihre Orientierung (Prozessor orientation), eine Zeile je IMU-Abtastwert.</translation>
    </message>
    <message>
        <source>Gates table: id, east, north, up (m), in course order.</source>
        <translation>Tortabelle: id, east, north, up (m), in Kursreihenfolge.</translation>
    </message>
    <message>
        <source>Sacrum x, y, z (m), vx, vy, vz, speed (m/s) in the gates&apos; frame.</source>
        <translation>Kreuzbein x, y, z (m), vx, vy, vz, speed (m/s) im System der Tore.</translation>
    </message>
    <message>
        <source>Detected gate crossings: t, gate, gate_to_gate (s since the previous crossing: the coach&apos;s gate-to-gate time), distance, excess, side, residual, pass-0 gate estimate.</source>
        <translation>Erkannte Tordurchfahrten: t, gate, gate_to_gate (s seit der vorigen Durchfahrt: die Tor-zu-Tor-Zeit des Trainers), distance, excess, side, residual, Torschätzung aus Durchgang 0.</translation>
    </message>
    <message>
        <source>Gate passages as predicted instants labelled &quot;gate&quot; (a lane in the action timeline).</source>
        <translation>Tordurchfahrten als vorhergesagte Zeitpunkte mit der Bezeichnung „gate“ (eine Spur in der Aktionszeitleiste).</translation>
    </message>
</context>
<context>
    <name>athlos::positioning::NoiseProfileProcessor</name>
    <message>
        <source>Noise profile</source>
        <translation>Rauschprofil</translation>
    </message>
    <message>
        <source>Estimates the position filter&apos;s process and measurement noise and outlier gate on up to eight training recordings of LPS fixes and stores them as a profile; position-filter applies it to new recordings with noise=profile:PATH.</source>
        <translation>Schätzt Prozess- und Messrauschen sowie das Ausreißertor des Positionsfilters auf bis zu acht Trainingsaufnahmen von LPS-Positionen und speichert sie als Profil; position-filter wendet es mit noise=profile:PATH auf neue Aufnahmen an.</translation>
    </message>
    <message>
        <source>LPS fixes t, x, y (m) of one training recording from the system the profile is for.</source>
        <translation>LPS-Positionen t, x, y (m) einer Trainingsaufnahme des Systems, für das das Profil gilt.</translation>
    </message>
    <message>
        <source>One row per noise parameter: parameter, value, unit; attribute model.</source>
        <translation>Eine Zeile je Rauschparameter: parameter, value, unit; Attribut model.</translation>
    </message>
</context>
<context>
    <name>athlos::positioning::PositionFilterProcessor</name>
    <message>
        <source>Position filter</source>
        <translation>Positionsfilter</translation>
    </message>
    <message>
        <source>Robust Kalman filtering of LPS positions (EKF, UKF or square-root UKF): outlier gating by the Mahalanobis distance, output on any time grid from non-uniform input, RTS or fixed-lag smoothing, noise parameters estimated from the data, and track constraints either in an augmented motion model or as pseudo-measurements.</source>
        <translation>Robuste Kalman-Filterung von LPS-Positionen (EKF, UKF oder Quadratwurzel-UKF): Ausreißertor über die Mahalanobis-Distanz, Ausgabe auf beliebigem Zeitraster aus ungleichmäßiger Eingabe, RTS- oder Fixed-Lag-Glättung, aus den Daten geschätzte Rauschparameter und Bahnbedingungen entweder in einem erweiterten Bewegungsmodell oder als Pseudomessungen.</translation>
    </message>
    <message>
        <source>Kalman filter variant.</source>
        <translation>Variante des Kalman-Filters.</translation>
    </message>
    <message>
        <source>Motion model: CTRA (unconstrained), CTRA with track pseudo-measurements, CTRA with the track-augmented prediction, or constant velocity. auto: augmented for position fixes (on the track), constant velocity for raw ranges (no track assumed).</source>
        <translation>Bewegungsmodell: CTRA (ohne Bedingung), CTRA mit Bahn-Pseudomessungen, CTRA mit bahnerweiterter Prädiktion oder konstante Geschwindigkeit. auto: erweitert für Positionen (auf der Bahn), konstante Geschwindigkeit für rohe Entfernungen (keine Bahn angenommen).</translation>
    </message>
    <message>
        <source>Track geometry: a name under the project&apos;s /geometry or a built-in (iaaf-400m, indoor-200m). Used by model=pseudo|augmented.</source>
        <translation>Bahngeometrie: ein Name unter /geometry des Projekts oder eine eingebaute (iaaf-400m, indoor-200m). Verwendet von model=pseudo|augmented.</translation>
    </message>
    <message>
        <source>Track origin x in LPS coordinates (overrides the geometry&apos;s pose).</source>
        <translation>Ursprung x der Bahn in LPS-Koordinaten (überschreibt die Lage der Geometrie).</translation>
    </message>
    <message>
        <source>Track origin y in LPS coordinates.</source>
        <translation>Ursprung y der Bahn in LPS-Koordinaten.</translation>
    </message>
    <message>
        <source>Rotation of the track frame in LPS coordinates (counter-clockwise).</source>
        <translation>Drehung des Bahnsystems in LPS-Koordinaten (gegen den Uhrzeigersinn).</translation>
    </message>
    <message>
        <source>auto: estimate Q, R and the gate from the input itself (innovation likelihood, no ground truth); manual: use the q_*, r_* and gate parameters; profile:PATH: the values of a noise-profile table estimated on training recordings (thesis §4.4 deployment), e.g. profile:training/noise.</source>
        <translation>auto: Q, R und das Tor aus der Eingabe selbst schätzen (Innovations-Likelihood, keine Referenz); manual: die Parameter q_*, r_* und gate verwenden; profile:PATH: die Werte einer auf Trainingsaufnahmen geschätzten noise-profile-Tabelle (Arbeit §4.4, Einsatz), z. B. profile:training/noise.</translation>
    </message>
    <message>
        <source>noise=auto estimates on this many evenly spread chunks of noise_chunk seconds (a representative subsample; 0 or a shorter recording: all of it).</source>
        <translation>noise=auto schätzt auf so vielen gleichmäßig verteilten Abschnitten von noise_chunk Sekunden (eine repräsentative Teilstichprobe; 0 oder eine kürzere Aufnahme: die ganze).</translation>
    </message>
    <message>
        <source>Raw ranges, noise=auto: each beacon&apos;s ranges at least this far apart for the estimate (range errors are correlated over fractions of a second; the likelihood assumes white noise).</source>
        <translation>Rohe Entfernungen, noise=auto: die Entfernungen jeder Bake für die Schätzung mindestens so weit auseinander (Entfernungsfehler sind über Sekundenbruchteile korreliert; die Likelihood nimmt weißes Rauschen an).</translation>
    </message>
    <message>
        <source>Length of one chunk of the noise estimate.</source>
        <translation>Länge eines Abschnitts der Rauschschätzung.</translation>
    </message>
    <message>
        <source>Process noise density of the position (manual).</source>
        <translation>Prozessrauschdichte der Position (manuell).</translation>
    </message>
    <message>
        <source>Process noise density of the speed (manual).</source>
        <translation>Prozessrauschdichte der Geschwindigkeit (manuell).</translation>
    </message>
    <message>
        <source>Process noise density of the acceleration; for constant-velocity the white-noise acceleration density (m^2/s^3) (manual).</source>
        <translation>Prozessrauschdichte der Beschleunigung; bei konstanter Geschwindigkeit die Dichte der Beschleunigung als weißes Rauschen (m^2/s^3) (manuell).</translation>
    </message>
    <message>
        <source>Process noise density of the heading (manual).</source>
        <translation>Prozessrauschdichte der Richtung (manuell).</translation>
    </message>
    <message>
        <source>Process noise density of the turn rate (manual).</source>
        <translation>Prozessrauschdichte der Drehrate (manuell).</translation>
    </message>
    <message>
        <source>Measurement noise variance in x (manual).</source>
        <translation>Varianz des Messrauschens in x (manuell).</translation>
    </message>
    <message>
        <source>Measurement noise variance in y (manual).</source>
        <translation>Varianz des Messrauschens in y (manuell).</translation>
    </message>
    <message>
        <source>Pseudo-measurement variance of heading − track heading (model=pseudo, manual).</source>
        <translation>Varianz der Pseudomessung Richtung − Bahnrichtung (model=pseudo, manuell).</translation>
    </message>
    <message>
        <source>Pseudo-measurement variance of turn rate − v·curvature (model=pseudo, manual).</source>
        <translation>Varianz der Pseudomessung Drehrate − v·Krümmung (model=pseudo, manuell).</translation>
    </message>
    <message>
        <source>Pseudo-measurement variance of the acceleration after the start (model=pseudo, manual).</source>
        <translation>Varianz der Pseudomessung der Beschleunigung nach dem Start (model=pseudo, manuell).</translation>
    </message>
    <message>
        <source>Range measurement noise variance (raw ranges, manual).</source>
        <translation>Varianz des Entfernungsmessrauschens (rohe Entfernungen, manuell).</translation>
    </message>
    <message>
        <source>Raw ranges: height of the tag in the beacons&apos; frame; the filter solves x, y at this height.</source>
        <translation>Rohe Entfernungen: Höhe des Tags im System der Baken; der Filter löst x, y auf dieser Höhe.</translation>
    </message>
    <message>
        <source>Raw ranges: estimate a constant range offset per beacon (antenna delay, survey error) with the track, for up to 8 beacons.</source>
        <translation>Rohe Entfernungen: einen konstanten Entfernungsoffset je Bake (Antennenverzögerung, Vermessungsfehler) zusammen mit der Bahn schätzen, für bis zu 8 Baken.</translation>
    </message>
    <message>
        <source>Raw ranges: prior standard deviation of each range offset.</source>
        <translation>Rohe Entfernungen: A-priori-Standardabweichung jedes Entfernungsoffsets.</translation>
    </message>
    <message>
        <source>Outlier gate α on the squared Mahalanobis distance of the innovation (manual); 0 disables gating.</source>
        <translation>Ausreißertor α auf der quadrierten Mahalanobis-Distanz der Innovation (manuell); 0 schaltet das Tor ab.</translation>
    </message>
    <message>
        <source>none: causal filter output (real-time behaviour); rts: Rauch–Tung–Striebel smoothing over the whole recording; fixed-lag: smoothing with `lag` seconds of look-ahead.</source>
        <translation>none: kausale Filterausgabe (Echtzeitverhalten); rts: Rauch–Tung–Striebel-Glättung über die ganze Aufnahme; fixed-lag: Glättung mit `lag` Sekunden Vorausschau.</translation>
    </message>
    <message>
        <source>Look-ahead of the fixed-lag smoother.</source>
        <translation>Vorausschau des Fixed-Lag-Glätters.</translation>
    </message>
    <message>
        <source>model=augmented with smoother=rts: outages at least this long are bridged along the track between the smoothed states at their ends (arc length by a monotone cubic matching both speeds); 0 = off.</source>
        <translation>model=augmented mit smoother=rts: Ausfälle mindestens dieser Länge werden entlang der Bahn zwischen den geglätteten Zuständen an ihren Enden überbrückt (Bogenlänge durch eine monotone Kubik, die beide Geschwindigkeiten trifft); 0 = aus.</translation>
    </message>
    <message>
        <source>Output on a uniform grid at this rate (multiples of 1/rate); absent: at the input time stamps.</source>
        <translation>Ausgabe auf einem gleichmäßigen Raster mit dieser Rate (Vielfache von 1/rate); fehlt sie: zu den Zeitstempeln der Eingabe.</translation>
    </message>
    <message>
        <source>Longest prediction step; outages are crossed in steps of at most this length.</source>
        <translation>Längster Prädiktionsschritt; Ausfälle werden in Schritten von höchstens dieser Länge überquert.</translation>
    </message>
    <message>
        <source>Track models: switch from constant acceleration to constant velocity after the start phase.</source>
        <translation>Bahnmodelle: nach der Startphase von konstanter Beschleunigung auf konstante Geschwindigkeit wechseln.</translation>
    </message>
    <message>
        <source>Duration of the constant-acceleration phase after the detected start.</source>
        <translation>Dauer der Phase konstanter Beschleunigung nach dem erkannten Start.</translation>
    </message>
    <message>
        <source>LPS fixes t, x, y (m), possibly non-uniform, with outliers and outages; or raw two-way ranges (lps-range) filtered tightly coupled, with the beacon table.</source>
        <translation>LPS-Positionen t, x, y (m), möglicherweise ungleichmäßig, mit Ausreißern und Ausfällen; oder rohe Zweiwege-Entfernungen (lps-range), eng gekoppelt gefiltert, mit der Bakentabelle.</translation>
    </message>
    <message>
        <source>Beacon table id, x, y, z (m) for raw ranges.</source>
        <translation>Bakentabelle id, x, y, z (m) für rohe Entfernungen.</translation>
    </message>
    <message>
        <source>x, y (m), speed (m/s), heading (rad), turn_rate (rad/s), accel (m/s^2), outlier (1 if an input sample in this output sample&apos;s interval was rejected); from raw ranges also sd_x, sd_y (m), the filter&apos;s position standard deviations.</source>
        <translation>x, y (m), speed (m/s), heading (rad), turn_rate (rad/s), accel (m/s^2), outlier (1, wenn ein Eingabe-Abtastwert im Intervall dieses Ausgabe-Abtastwerts verworfen wurde); aus rohen Entfernungen auch sd_x, sd_y (m), die Standardabweichungen der Position im Filter.</translation>
    </message>
    <message>
        <source>Per input sample: outlier (0/1) and mahalanobis (squared distance d^2).</source>
        <translation>Je Eingabe-Abtastwert: outlier (0/1) und mahalanobis (quadrierte Distanz d^2).</translation>
    </message>
</context>
<context>
    <name>athlos::positioning::SimulateGatesProcessor</name>
    <message>
        <source>Simulate giant-slalom run with gate magnets</source>
        <translation>Riesenslalom-Lauf mit Tormagneten simulieren</translation>
    </message>
    <message>
        <source>Simulates a giant-slalom run (turns about 27 m apart at 15-25 m/s, standing at start and finish) with a sacrum IMU (bias, noise, gyroscope drift, vibration) and magnets buried at the gates whose field adds to the magnetometer (Fasel thesis eq. 9.1), plus the truth and the gate table.</source>
        <translation>Simuliert einen Riesenslalom-Lauf (Schwünge etwa 27 m auseinander bei 15–25 m/s, Stehen an Start und Ziel) mit einer Kreuzbein-IMU (Bias, Rauschen, Gyroskopdrift, Vibration) und an den Toren vergrabenen Magneten, deren Feld zum Magnetometer hinzukommt (Arbeit von Fasel Gl. 9.1), dazu die Referenz und die Tortabelle.</translation>
    </message>
    <message>
        <source>Random seed (deterministic).</source>
        <translation>Zufallsstartwert (deterministisch).</translation>
    </message>
    <message>
        <source>Seed of the gates&apos; magnet offsets; the same value gives the same course for several runs (0: from seed).</source>
        <translation>Startwert der Magnetversätze der Tore; derselbe Wert ergibt denselben Kurs für mehrere Läufe (0: aus seed).</translation>
    </message>
    <message>
        <source>Number of gates (one turn each).</source>
        <translation>Anzahl der Tore (je ein Schwung).</translation>
    </message>
    <message>
        <source>Distance between turns along the fall line (thesis course: 21.8-27.8 m between gates).</source>
        <translation>Abstand zwischen den Schwüngen entlang der Falllinie (Kurs der Arbeit: 21,8–27,8 m zwischen den Toren).</translation>
    </message>
    <message>
        <source>Lateral excursion of the sacrum line.</source>
        <translation>Seitliche Auslenkung der Kreuzbeinlinie.</translation>
    </message>
    <message>
        <source>Slope angle.</source>
        <translation>Hangwinkel.</translation>
    </message>
    <message>
        <source>Mean speed.</source>
        <translation>Mittlere Geschwindigkeit.</translation>
    </message>
    <message>
        <source>Slow speed variation around the mean.</source>
        <translation>Langsame Geschwindigkeitsschwankung um den Mittelwert.</translation>
    </message>
    <message>
        <source>Sampling rate of the IMU (acc, gyr, mag).</source>
        <translation>Abtastrate der IMU (acc, gyr, mag).</translation>
    </message>
    <message>
        <source>Gyroscope bias, SD per axis (0.15 deg/s drift).</source>
        <translation>Gyroskop-Bias, SD je Achse (0,15 deg/s Drift).</translation>
    </message>
    <message>
        <source>Standing time at the start and at the finish.</source>
        <translation>Stehzeit an Start und Ziel.</translation>
    </message>
    <message>
        <source>Simulated sacrum IMU: acc, gyr, mag.</source>
        <translation>Simulierte Kreuzbein-IMU: acc, gyr, mag.</translation>
    </message>
    <message>
        <source>Ground truth x, y, z (m), vx, vy, vz, speed (m/s), ENU.</source>
        <translation>Referenz x, y, z (m), vx, vy, vz, speed (m/s), ENU.</translation>
    </message>
    <message>
        <source>Magnet positions: id, east, north, up (m).</source>
        <translation>Magnetpositionen: id, east, north, up (m).</translation>
    </message>
</context>
<context>
    <name>athlos::positioning::SimulateTrackRunProcessor</name>
    <message>
        <source>Simulate track run</source>
        <translation>Bahnlauf simulieren</translation>
    </message>
    <message>
        <source>Simulates an LPS recording of a runner on a track (start acceleration, near-constant speed, lane changes) with tag noise, outlier bursts, non-uniform sampling and outages, plus the ground truth.</source>
        <translation>Simuliert eine LPS-Aufnahme eines Läufers auf einer Bahn (Startbeschleunigung, nahezu konstante Geschwindigkeit, Bahnwechsel) mit Tag-Rauschen, Ausreißerfolgen, ungleichmäßiger Abtastung und Ausfällen, dazu die Referenz.</translation>
    </message>
    <message>
        <source>Random seed (deterministic).</source>
        <translation>Zufallsstartwert (deterministisch).</translation>
    </message>
    <message>
        <source>Race distance.</source>
        <translation>Renndistanz.</translation>
    </message>
    <message>
        <source>Start lane.</source>
        <translation>Startbahn.</translation>
    </message>
    <message>
        <source>Speed after the start.</source>
        <translation>Geschwindigkeit nach dem Start.</translation>
    </message>
    <message>
        <source>Time constant of the start acceleration.</source>
        <translation>Zeitkonstante der Startbeschleunigung.</translation>
    </message>
    <message>
        <source>Fraction of the top speed lost linearly over the distance.</source>
        <translation>Anteil der Höchstgeschwindigkeit, der linear über die Distanz verloren geht.</translation>
    </message>
    <message>
        <source>SD of the speed fluctuation (Ornstein–Uhlenbeck, 3 s).</source>
        <translation>SD der Geschwindigkeitsschwankung (Ornstein–Uhlenbeck, 3 s).</translation>
    </message>
    <message>
        <source>Standing time before the start.</source>
        <translation>Stehzeit vor dem Start.</translation>
    </message>
    <message>
        <source>Recorded time after the finish.</source>
        <translation>Aufgezeichnete Zeit nach dem Ziel.</translation>
    </message>
    <message>
        <source>800 m break to lane 1 after the first bend and random overtakes.</source>
        <translation>800 m: Wechsel auf Bahn 1 nach der ersten Kurve und zufällige Überholmanöver.</translation>
    </message>
    <message>
        <source>Tag noise variance in x.</source>
        <translation>Varianz des Tag-Rauschens in x.</translation>
    </message>
    <message>
        <source>Tag noise variance in y.</source>
        <translation>Varianz des Tag-Rauschens in y.</translation>
    </message>
    <message>
        <source>Fraction of outliers.</source>
        <translation>Anteil der Ausreißer.</translation>
    </message>
    <message>
        <source>Mean outlier burst length (samples).</source>
        <translation>Mittlere Länge einer Ausreißerfolge (Abtastwerte).</translation>
    </message>
    <message>
        <source>SD of outliers per axis.</source>
        <translation>SD der Ausreißer je Achse.</translation>
    </message>
    <message>
        <source>Mean number of outages per 400 m.</source>
        <translation>Mittlere Anzahl der Ausfälle je 400 m.</translation>
    </message>
    <message>
        <source>Shortest outage.</source>
        <translation>Kürzester Ausfall.</translation>
    </message>
    <message>
        <source>Longest outage.</source>
        <translation>Längster Ausfall.</translation>
    </message>
    <message>
        <source>Sampling rate of the truth (a divisor of 1000).</source>
        <translation>Abtastrate der Referenz (ein Teiler von 1000).</translation>
    </message>
    <message>
        <source>Track geometry: a name under the project&apos;s /geometry or a built-in.</source>
        <translation>Bahngeometrie: ein Name unter /geometry des Projekts oder eine eingebaute.</translation>
    </message>
    <message>
        <source>Track origin x in LPS coordinates.</source>
        <translation>Ursprung x der Bahn in LPS-Koordinaten.</translation>
    </message>
    <message>
        <source>Track origin y in LPS coordinates.</source>
        <translation>Ursprung y der Bahn in LPS-Koordinaten.</translation>
    </message>
    <message>
        <source>Rotation of the track frame.</source>
        <translation>Drehung des Bahnsystems.</translation>
    </message>
    <message>
        <source>Simulated LPS fixes t, x, y (m).</source>
        <translation>Simulierte LPS-Positionen t, x, y (m).</translation>
    </message>
    <message>
        <source>Ground truth t, x, y (m), speed (m/s), heading (rad).</source>
        <translation>Referenz t, x, y (m), speed (m/s), heading (rad).</translation>
    </message>
</context>
<context>
    <name>athlos::signal::ButterworthProcessor</name>
    <message>
        <source>Butterworth filter</source>
        <translation>Butterworth-Filter</translation>
    </message>
    <message>
        <source>Low-pass, high-pass, band-pass or band-stop Butterworth filter of selected columns, zero-phase (forward-backward) by default. Needs uniform sampling (run resample first). Quaternion and flag columns pass through unchanged; NaN-free runs are filtered separately.</source>
        <translation>Butterworth-Tiefpass, -Hochpass, -Bandpass oder -Bandsperre auf ausgewählten Spalten, standardmäßig nullphasig (vorwärts-rückwärts). Benötigt gleichmäßige Abtastung (zuerst resample ausführen). Quaternionen- und Flag-Spalten bleiben unverändert; NaN-freie Abschnitte werden getrennt gefiltert.</translation>
    </message>
    <message>
        <source>Cut-off frequency (-3 dB of one pass); the lower edge for bandpass/bandstop. Must be below half the sampling rate.</source>
        <translation>Grenzfrequenz (−3 dB eines Durchgangs); die untere Kante bei bandpass/bandstop. Muss unter der halben Abtastrate liegen.</translation>
    </message>
    <message>
        <source>Upper edge for bandpass/bandstop (required there, not allowed otherwise).</source>
        <translation>Obere Kante bei bandpass/bandstop (dort erforderlich, sonst nicht erlaubt).</translation>
    </message>
    <message>
        <source>Filter type.</source>
        <translation>Filtertyp.</translation>
    </message>
    <message>
        <source>Filter order n (band types have 2n poles). Zero-phase filtering doubles the effective order.</source>
        <translation>Filterordnung n (Bandtypen haben 2n Pole). Nullphasige Filterung verdoppelt die wirksame Ordnung.</translation>
    </message>
    <message>
        <source>Filter forwards and backwards (no phase shift, squared magnitude: -6 dB at the cut-off); false = causal single pass.</source>
        <translation>Vorwärts und rückwärts filtern (keine Phasenverschiebung, quadrierter Betrag: −6 dB an der Grenzfrequenz); false = kausaler einfacher Durchgang.</translation>
    </message>
    <message>
        <source>Comma-separated columns to filter; empty = all columns except quaternions and flags.</source>
        <translation>Durch Kommas getrennte zu filternde Spalten; leer = alle Spalten außer Quaternionen und Flags.</translation>
    </message>
    <message>
        <source>Uniformly sampled stream of any kind.</source>
        <translation>Gleichmäßig abgetasteter Datenstrom beliebiger Art.</translation>
    </message>
    <message>
        <source>Filtered stream: same kind, frame and columns.</source>
        <translation>Gefilterter Datenstrom: dieselbe Art, dasselbe Bezugssystem und dieselben Spalten.</translation>
    </message>
</context>
<context>
    <name>athlos::signal::ResampleProcessor</name>
    <message>
        <source>Resample</source>
        <translation>Neu abtasten</translation>
    </message>
    <message>
        <source>Resamples a stream onto a uniform time grid: linear, nearest or cubic interpolation of ordinary columns, SLERP of quaternions (qw,qx,qy,qz, any prefix), nearest neighbour for flag columns; optionally NaN inside input gaps longer than max_gap.</source>
        <translation>Tastet einen Datenstrom auf ein gleichmäßiges Zeitraster um: lineare, nächste oder kubische Interpolation gewöhnlicher Spalten, SLERP für Quaternionen (qw,qx,qy,qz, beliebiges Präfix), nächster Nachbar für Flag-Spalten; optional NaN in Eingabelücken, die länger als max_gap sind.</translation>
    </message>
    <message>
        <source>Output sampling rate (&gt; 0).</source>
        <translation>Ausgabe-Abtastrate (&gt; 0).</translation>
    </message>
    <message>
        <source>Interpolation of ordinary columns. cubic = local cubic Hermite (Catmull-Rom style, exact for quadratics). Quaternions always use SLERP (nearest sample for nearest), flags nearest.</source>
        <translation>Interpolation gewöhnlicher Spalten. cubic = lokale kubische Hermite-Interpolation (nach Catmull-Rom, exakt für quadratische Funktionen). Quaternionen verwenden immer SLERP (nächster Abtastwert bei nearest), Flags den nächsten.</translation>
    </message>
    <message>
        <source>Output samples inside an input gap longer than this become NaN; 0 = off.</source>
        <translation>Ausgabe-Abtastwerte in einer Eingabelücke, die länger ist, werden NaN; 0 = aus.</translation>
    </message>
    <message>
        <source>Put the grid on integer multiples of 1/rate instead of starting at the first sample.</source>
        <translation>Das Raster auf ganzzahlige Vielfache von 1/rate legen, statt beim ersten Abtastwert zu beginnen.</translation>
    </message>
    <message>
        <source>Stream of any kind, possibly non-uniform.</source>
        <translation>Datenstrom beliebiger Art, möglicherweise ungleichmäßig.</translation>
    </message>
    <message>
        <source>Uniformly sampled stream: same kind, frame and columns.</source>
        <translation>Gleichmäßig abgetasteter Datenstrom: dieselbe Art, dasselbe Bezugssystem und dieselben Spalten.</translation>
    </message>
</context>
<context>
    <name>athlos::team::SimulateTeamProcessor</name>
    <message>
        <source>Simulate team match</source>
        <translation>Mannschaftsspiel simulieren</translation>
    </message>
    <message>
        <source>Simulates a football match: 22 players (two teams in a 4-4-2 with goalkeepers) on a 105 × 68 m pitch, with standing, walking, jogging, running and sprinting phases, bounded accelerations and the team blocks shifting with the ball. One position stream per player.</source>
        <translation>Simuliert ein Fußballspiel: 22 Spieler (zwei Mannschaften im 4-4-2 mit Torhütern) auf einem Feld von 105 × 68 m, mit Phasen des Stehens, Gehens, Trabens, Laufens und Sprintens, begrenzten Beschleunigungen und mit dem Ball verschiebenden Mannschaftsblöcken. Ein Positionsdatenstrom je Spieler.</translation>
    </message>
    <message>
        <source>Random seed (deterministic).</source>
        <translation>Zufallsstartwert (deterministisch).</translation>
    </message>
    <message>
        <source>Playing time.</source>
        <translation>Spielzeit.</translation>
    </message>
    <message>
        <source>Sampling rate of the positions.</source>
        <translation>Abtastrate der Positionen.</translation>
    </message>
    <message>
        <source>Largest acceleration of a player (vector norm).</source>
        <translation>Größte Beschleunigung eines Spielers (Vektornorm).</translation>
    </message>
    <message>
        <source>Slowest sprint speed among the players.</source>
        <translation>Langsamste Sprintgeschwindigkeit unter den Spielern.</translation>
    </message>
    <message>
        <source>Fastest sprint speed among the players.</source>
        <translation>Schnellste Sprintgeschwindigkeit unter den Spielern.</translation>
    </message>
    <message>
        <source>How readily players choose running and sprinting (1 = typical).</source>
        <translation>Wie bereitwillig Spieler Laufen und Sprinten wählen (1 = typisch).</translation>
    </message>
    <message>
        <source>Positions t, x, y (m) of player %1.</source>
        <translation>Positionen t, x, y (m) von Spieler %1.</translation>
    </message>
</context>
<context>
    <name>athlos::ui</name>
    <message>
        <source>Export report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>Open a project first.</source>
        <translation>Öffnen Sie zuerst ein Projekt.</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Computing session metrics…</source>
        <translation>Einheitskennzahlen werden berechnet…</translation>
    </message>
    <message>
        <source>Writing the report…</source>
        <translation>Bericht wird geschrieben…</translation>
    </message>
    <message>
        <source>time (min)</source>
        <translation>Zeit (min)</translation>
    </message>
    <message>
        <source>speed (km/h)</source>
        <translation>Geschwindigkeit (km/h)</translation>
    </message>
    <message>
        <source>Export gait report</source>
        <translation>Ganganalyse-Bericht exportieren</translation>
    </message>
    <message>
        <source>Choose a stride table.</source>
        <translation>Wählen Sie eine Schritttabelle.</translation>
    </message>
    <message>
        <source>Writing the gait report…</source>
        <translation>Ganganalyse-Bericht wird geschrieben…</translation>
    </message>
    <message>
        <source>turns (|turning angle| &gt; %1 rad)</source>
        <translation>Wendungen (|Drehwinkel| &gt; %1 rad)</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ActionTimeline</name>
    <message>
        <source>No annotations in this recording. Annotate on the time series or run an event detector (e.g. gait-events).</source>
        <translation>Keine Annotationen in dieser Aufnahme. Annotieren Sie in der Zeitreihe oder starten Sie einen Ereignisdetektor (z. B. gait-events).</translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <source> · %1 s</source>
        <translation> · %1 s</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ActionsView</name>
    <message>
        <source>Recording:</source>
        <translation>Aufnahme:</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Read the annotations again (after a processor run).</source>
        <translation>Annotationen neu einlesen (nach einem Prozessorlauf).</translation>
    </message>
    <message>
        <source>Solid: manual annotations. Hatched: predicted by a processor, more opaque with higher confidence. Click to move the time cursor.</source>
        <translation>Gefüllt: manuelle Annotationen. Schraffiert: von einem Prozessor vorhergesagt, umso deckender, je höher die Konfidenz. Klicken setzt den Zeitcursor.</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>Predicted</source>
        <translation>Vorhergesagt</translation>
    </message>
    <message>
        <source>Mean (s)</source>
        <translation>Mittel (s)</translation>
    </message>
    <message>
        <source>Confidence</source>
        <translation>Konfidenz</translation>
    </message>
    <message>
        <source>Mean duration of the intervals</source>
        <translation>Mittlere Dauer der Intervalle</translation>
    </message>
    <message>
        <source>Mean confidence of the predicted ones</source>
        <translation>Mittlere Konfidenz der vorhergesagten</translation>
    </message>
    <message>
        <source>◀ Previous</source>
        <translation>◀ Zurück</translation>
    </message>
    <message>
        <source>Next ▶</source>
        <translation>Weiter ▶</translation>
    </message>
    <message>
        <source>Accept</source>
        <translation>Übernehmen</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Previous predicted action</source>
        <translation>Vorherige vorhergesagte Aktion</translation>
    </message>
    <message>
        <source>Next predicted action</source>
        <translation>Nächste vorhergesagte Aktion</translation>
    </message>
    <message>
        <source>Keep the predicted action as a reviewed manual annotation (undoable).</source>
        <translation>Die vorhergesagte Aktion als geprüfte manuelle Annotation behalten (rückgängig machbar).</translation>
    </message>
    <message>
        <source>Delete the predicted action (undoable).</source>
        <translation>Die vorhergesagte Aktion löschen (rückgängig machbar).</translation>
    </message>
    <message>
        <source>Review:</source>
        <translation>Prüfen:</translation>
    </message>
    <message>
        <source>no recording &apos;%1&apos; in this project</source>
        <translation>keine Aufnahme „%1“ in diesem Projekt</translation>
    </message>
    <message numerus="yes">
        <source>%n annotation(s)</source>
        <translation>
            <numerusform>%n Annotation</numerusform>
            <numerusform>%n Annotationen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n predicted</source>
        <translation>
            <numerusform>%n vorhergesagt</numerusform>
            <numerusform>%n vorhergesagt</numerusform>
        </translation>
    </message>
    <message>
        <source>Reviewing needs the annotation editor of the main window.</source>
        <translation>Zum Prüfen wird der Annotationseditor des Hauptfensters benötigt.</translation>
    </message>
    <message>
        <source>No predicted action selected; use Next.</source>
        <translation>Keine vorhergesagte Aktion ausgewählt; verwenden Sie „Weiter“.</translation>
    </message>
    <message>
        <source>No predicted actions to review.</source>
        <translation>Keine vorhergesagten Aktionen zu prüfen.</translation>
    </message>
    <message numerus="yes">
        <source>%n predicted action(s) to review; press Next.</source>
        <translation>
            <numerusform>%n vorhergesagte Aktion zu prüfen; drücken Sie Weiter.</numerusform>
            <numerusform>%n vorhergesagte Aktionen zu prüfen; drücken Sie Weiter.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2: %3, %4–%5 s, confidence %6</source>
        <translation>%1 von %2: %3, %4–%5 s, Konfidenz %6</translation>
    </message>
    <message>
        <source>Action timeline</source>
        <translation>Aktionszeitleiste</translation>
    </message>
    <message>
        <source>no annotations in this project; run an event detector (e.g. gait-events) or annotate first</source>
        <translation>keine Annotationen in diesem Projekt; starten Sie zuerst einen Ereignisdetektor (z. B. gait-events) oder annotieren Sie</translation>
    </message>
    <message>
        <source>recording &apos;%1&apos; has no stream to plot</source>
        <translation>Aufnahme „%1“ hat keinen Datenstrom zum Anzeigen</translation>
    </message>
</context>
<context>
    <name>athlos::ui::AnnotationEditor</name>
    <message>
        <source>Open a project first.</source>
        <translation>Öffnen Sie zuerst ein Projekt.</translation>
    </message>
    <message>
        <source>The project is being saved; try again in a moment.</source>
        <translation>Das Projekt wird gerade gespeichert; versuchen Sie es gleich noch einmal.</translation>
    </message>
    <message>
        <source>No recording &apos;%1&apos;.</source>
        <translation>Keine Aufnahme „%1“.</translation>
    </message>
    <message>
        <source>No annotation %1 in &apos;%2&apos;.</source>
        <translation>Keine Annotation %1 in „%2“.</translation>
    </message>
    <message>
        <source>Choose or add an annotation class first.</source>
        <translation>Wählen Sie zuerst eine Annotationsklasse oder legen Sie eine an.</translation>
    </message>
    <message>
        <source>An annotation needs a start before its end.</source>
        <translation>Eine Annotation braucht einen Anfang vor ihrem Ende.</translation>
    </message>
    <message>
        <source>Create %1</source>
        <translation>%1 anlegen</translation>
    </message>
    <message>
        <source>Edit %1</source>
        <translation>%1 bearbeiten</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <source>A class needs a name.</source>
        <translation>Eine Klasse braucht einen Namen.</translation>
    </message>
</context>
<context>
    <name>athlos::ui::AnnotationPanel</name>
    <message>
        <source>Class of new intervals (keys 1–9 on the plot)</source>
        <translation>Klasse neuer Intervalle (Tasten 1–9 im Diagramm)</translation>
    </message>
    <message>
        <source>Add Class…</source>
        <translation>Klasse hinzufügen…</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <source>Start [s]</source>
        <translation>Beginn [s]</translation>
    </message>
    <message>
        <source>End [s]</source>
        <translation>Ende [s]</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Next to Review</source>
        <translation>Nächste prüfen</translation>
    </message>
    <message>
        <source>Select the next annotation made by a processor</source>
        <translation>Die nächste von einem Prozessor erzeugte Annotation auswählen</translation>
    </message>
    <message>
        <source>Accept</source>
        <translation>Annehmen</translation>
    </message>
    <message>
        <source>Reject</source>
        <translation>Verwerfen</translation>
    </message>
    <message>
        <source>Classes:</source>
        <translation>Klassen:</translation>
    </message>
    <message>
        <source>manual (%1)</source>
        <translation>manuell (%1)</translation>
    </message>
    <message>
        <source>%1, %2% confident</source>
        <translation>%1, %2 % sicher</translation>
    </message>
    <message>
        <source>Select a stream to annotate its recording.</source>
        <translation>Wählen Sie einen Datenstrom, um seine Aufnahme zu annotieren.</translation>
    </message>
    <message>
        <source>No annotations on %1 yet. Shift+drag on the plot (or use annotate mode) to add one.</source>
        <translation>Noch keine Annotationen in %1. Umschalt+Ziehen im Diagramm (oder der Annotationsmodus) legt eine an.</translation>
    </message>
    <message>
        <source>Annotations to review: %1</source>
        <translation>Zu prüfende Annotationen: %1</translation>
    </message>
    <message>
        <source>Nothing left to review.</source>
        <translation>Nichts mehr zu prüfen.</translation>
    </message>
    <message>
        <source>Add Annotation Class</source>
        <translation>Annotationsklasse hinzufügen</translation>
    </message>
    <message>
        <source>Class name:</source>
        <translation>Klassenname:</translation>
    </message>
</context>
<context>
    <name>athlos::ui::BackgroundTask</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>athlos::ui::CycleNormalisedView</name>
    <message>
        <source>Recording</source>
        <translation>Aufnahme</translation>
    </message>
    <message>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Zyklen</translation>
    </message>
    <message>
        <source>recording &apos;%1&apos; has no cycle annotations</source>
        <translation>Aufnahme „%1“ hat keine Zyklus-Annotationen</translation>
    </message>
    <message>
        <source>no stream &apos;%1&apos; in recording &apos;%2&apos;</source>
        <translation>kein Datenstrom „%1“ in Aufnahme „%2“</translation>
    </message>
    <message>
        <source>stream &apos;%1&apos; has no column &apos;%2&apos;</source>
        <translation>Datenstrom „%1“ hat keine Spalte „%2“</translation>
    </message>
    <message>
        <source>no cycles labelled &apos;%1&apos; in recording &apos;%2&apos;</source>
        <translation>keine Zyklen mit der Bezeichnung „%1“ in Aufnahme „%2“</translation>
    </message>
    <message>
        <source>Choose a recording with cycle annotations (e.g. from xc-skiing-cycles, alpine-turns or gait-events), a signal and the cycles.</source>
        <translation>Wählen Sie eine Aufnahme mit Zyklus-Annotationen (z. B. aus xc-skiing-cycles, alpine-turns oder gait-events), ein Signal und die Zyklen.</translation>
    </message>
    <message numerus="yes">
        <source>%n cycle(s), mean ± SD</source>
        <translation>
            <numerusform>%n Zyklus, Mittel ± SD</numerusform>
            <numerusform>%n Zyklen, Mittel ± SD</numerusform>
        </translation>
    </message>
    <message>
        <source>double turn (%): left 0–100, right 100–200</source>
        <translation>Doppelschwung (%): links 0–100, rechts 100–200</translation>
    </message>
    <message>
        <source>cycle (%)</source>
        <translation>Zyklus (%)</translation>
    </message>
</context>
<context>
    <name>athlos::ui::CycleTableView</name>
    <message>
        <source>Table</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a table with start and end columns</source>
        <translation>&apos;%1&apos; ist keine Tabelle mit Spalten start und end</translation>
    </message>
    <message>
        <source>No table with start and end columns in this project (run gait-parameters, xc-skiing-cycles or velocity-reset first).</source>
        <translation>Keine Tabelle mit Spalten start und end in diesem Projekt (zuerst gait-parameters, xc-skiing-cycles oder velocity-reset ausführen).</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>SD</source>
        <translation>SA</translation>
    </message>
    <message numerus="yes">
        <source>%n row(s); the row under the cursor is selected, a click shows its cycle</source>
        <translation>
            <numerusform>%n Zeile; die Zeile unter dem Cursor ist ausgewählt, ein Klick zeigt ihren Zyklus</numerusform>
            <numerusform>%n Zeilen; die Zeile unter dem Cursor ist ausgewählt, ein Klick zeigt ihren Zyklus</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>athlos::ui::FunctionalCalibrationWizard</name>
    <message>
        <source>Functional calibration</source>
        <translation>Funktionelle Kalibrierung</translation>
    </message>
    <message>
        <source>Recording and sensors</source>
        <translation>Aufnahme und Sensoren</translation>
    </message>
    <message>
        <source>The recording of the protocol: standing upright still (10 s) with the arms hanging, 3 squats, 3 trunk rotations, 3 hip ab/adductions per leg and, for arm sensors, 3 arm swings holding a pole horizontally, standing still for a moment between movements. Choose the IMU of each segment (leave out those without a sensor). Next finds the movements and calibrates.</source>
        <translation>Die Aufnahme des Protokolls: ruhig aufrecht stehen (10 s) mit hängenden Armen, 3 Kniebeugen, 3 Rumpfrotationen, 3 Hüft-Ab-/Adduktionen je Bein und, bei Armsensoren, 3 Armschwünge mit waagrecht gehaltenem Stock, zwischen den Bewegungen kurz stillstehen. Wählen Sie die IMU jedes Segments (lassen Sie die ohne Sensor weg). Weiter findet die Bewegungen und kalibriert.</translation>
    </message>
    <message>
        <source>Recording:</source>
        <translation>Aufnahme:</translation>
    </message>
    <message>
        <source>Output (rec/table):</source>
        <translation>Ausgabe (Aufnahme/Tabelle):</translation>
    </message>
    <message>
        <source>This project has no IMU stream; import the recording first.</source>
        <translation>Dieses Projekt hat keinen IMU-Datenstrom; importieren Sie zuerst die Aufnahme.</translation>
    </message>
    <message>
        <source>Movements and quality</source>
        <translation>Bewegungen und Qualität</translation>
    </message>
    <message>
        <source>The movements found and, per segment, the dispersion χ of the functional axis between repetitions, its angle to the horizontal plane, the angle between axes that should be orthogonal and the CMC of the repetitions. Finish keeps the calibration; Back discards it.</source>
        <translation>Die gefundenen Bewegungen und je Segment die Streuung χ der funktionellen Achse zwischen Wiederholungen, ihr Winkel zur horizontalen Ebene, der Winkel zwischen Achsen, die orthogonal sein sollten, und der CMC der Wiederholungen. Fertigstellen behält die Kalibrierung; Zurück verwirft sie.</translation>
    </message>
    <message>
        <source>Movements:</source>
        <translation>Bewegungen:</translation>
    </message>
    <message>
        <source>Quality per segment:</source>
        <translation>Qualität je Segment:</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Choose the IMU stream of at least one segment.</source>
        <translation>Wählen Sie den IMU-Datenstrom mindestens eines Segments.</translation>
    </message>
    <message>
        <source>The output must be named rec/table.</source>
        <translation>Die Ausgabe muss als Aufnahme/Tabelle benannt sein.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; already exists; choose another name.</source>
        <translation>„%1“ existiert bereits; wählen Sie einen anderen Namen.</translation>
    </message>
    <message>
        <source>Movement</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>Repetition</source>
        <translation>Wiederholung</translation>
    </message>
    <message>
        <source>From [s]</source>
        <translation>Von [s]</translation>
    </message>
    <message>
        <source>To [s]</source>
        <translation>Bis [s]</translation>
    </message>
    <message>
        <source> (marked)</source>
        <translation> (markiert)</translation>
    </message>
    <message>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <source>χ [°]</source>
        <translation>χ [°]</translation>
    </message>
    <message>
        <source>Orthogonality [°]</source>
        <translation>Orthogonalität [°]</translation>
    </message>
    <message>
        <source>Second axis [°]</source>
        <translation>Zweite Achse [°]</translation>
    </message>
    <message>
        <source>CMC</source>
        <translation>CMC</translation>
    </message>
</context>
<context>
    <name>athlos::ui::GaitReport</name>
    <message>
        <source>Stride length</source>
        <translation>Doppelschrittlänge</translation>
    </message>
    <message>
        <source>Stride height</source>
        <translation>Doppelschritthöhe</translation>
    </message>
    <message>
        <source>Stride time</source>
        <translation>Doppelschrittdauer</translation>
    </message>
    <message>
        <source>Stance time</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>Swing time</source>
        <translation>Schwungphase</translation>
    </message>
    <message>
        <source>Cadence</source>
        <translation>Kadenz</translation>
    </message>
    <message>
        <source>Gait speed</source>
        <translation>Ganggeschwindigkeit</translation>
    </message>
    <message>
        <source>Max. toe clearance</source>
        <translation>Max. Fußfreiheit</translation>
    </message>
    <message>
        <source>Athlos gait report</source>
        <translation>Athlos Ganganalyse-Bericht</translation>
    </message>
    <message>
        <source>Gait report: %1</source>
        <translation>Ganganalyse: %1</translation>
    </message>
    <message>
        <source>%1 · %2 · generated %3 by Athlos</source>
        <translation>%1 · %2 · erstellt %3 von Athlos</translation>
    </message>
    <message>
        <source>Strides from mid-stance to mid-stance of a foot-mounted IMU (gait-parameters, method %1). Steady state (gait-summary): strides with |turning angle| ≤ %2 rad on terrain &apos;%3&apos;, without the first and last %4 stride(s) of each run of straight strides. SD: sample standard deviation; CV = SD / mean; SI: symmetry index 100 |left − right| / mean of both (Robinson et al. 1987).</source>
        <translation>Doppelschritte von Mittstand zu Mittstand einer am Fuß getragenen IMU (gait-parameters, Methode %1). Stationärer Gang (gait-summary): Doppelschritte mit |Drehwinkel| ≤ %2 rad auf Gelände &apos;%3&apos;, ohne die ersten und letzten %4 Doppelschritt(e) jeder Folge gerader Doppelschritte. SA: Stichproben-Standardabweichung; CV = SA / Mittelwert; SI: Symmetrieindex 100 |links − rechts| / Mittel beider (Robinson et al. 1987).</translation>
    </message>
    <message>
        <source>%1: %2 of %3 strides in the steady state</source>
        <translation>%1: %2 von %3 Doppelschritten im stationären Gang</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>%1 mean</source>
        <translation>%1 Mittel</translation>
    </message>
    <message>
        <source>SD</source>
        <translation>SA</translation>
    </message>
    <message>
        <source>CV %</source>
        <translation>CV %</translation>
    </message>
    <message>
        <source>both mean</source>
        <translation>beide Mittel</translation>
    </message>
    <message>
        <source>SI %</source>
        <translation>SI %</translation>
    </message>
    <message>
        <source>stride length (m)</source>
        <translation>Doppelschrittlänge (m)</translation>
    </message>
    <message>
        <source>gait speed (m/s)</source>
        <translation>Ganggeschwindigkeit (m/s)</translation>
    </message>
    <message>
        <source>Foot</source>
        <translation>Fuß</translation>
    </message>
    <message>
        <source>Start s</source>
        <translation>Beginn s</translation>
    </message>
    <message>
        <source>Length m</source>
        <translation>Länge m</translation>
    </message>
    <message>
        <source>Height m</source>
        <translation>Höhe m</translation>
    </message>
    <message>
        <source>Time s</source>
        <translation>Dauer s</translation>
    </message>
    <message>
        <source>Stance %</source>
        <translation>Stand %</translation>
    </message>
    <message>
        <source>Speed m/s</source>
        <translation>Tempo m/s</translation>
    </message>
    <message>
        <source>Clearance m</source>
        <translation>Fußfreiheit m</translation>
    </message>
    <message>
        <source>Turn °</source>
        <translation>Drehung °</translation>
    </message>
    <message>
        <source>Strides (%1)</source>
        <translation>Doppelschritte (%1)</translation>
    </message>
</context>
<context>
    <name>athlos::ui::GaitReportDialog</name>
    <message>
        <source>Export gait report</source>
        <translation>Ganganalyse-Bericht exportieren</translation>
    </message>
    <message>
        <source>Stride tables of &apos;%1&apos; (gait-parameters), one per foot:</source>
        <translation>Schritttabellen von &apos;%1&apos; (gait-parameters), eine pro Fuß:</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Left foot (or the only one):</source>
        <translation>Linker Fuß (oder der einzige):</translation>
    </message>
    <message>
        <source>Right foot:</source>
        <translation>Rechter Fuß:</translation>
    </message>
    <message>
        <source>Steady state (gait-summary):</source>
        <translation>Stationärer Gang (gait-summary):</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ImportWizard</name>
    <message>
        <source>Import Wizard</source>
        <translation>Import-Assistent</translation>
    </message>
    <message>
        <source>Checking %1 file(s)…</source>
        <translation>%1 Datei(en) werden geprüft …</translation>
    </message>
    <message>
        <source>The check was cancelled; check again before importing.</source>
        <translation>Die Prüfung wurde abgebrochen; vor dem Import erneut prüfen.</translation>
    </message>
    <message>
        <source>%1: the recording name is empty</source>
        <translation>%1: Der Name der Aufnahme ist leer</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is imported from another file as well; give it another name</source>
        <translation>%1: &apos;%2&apos; wird auch aus einer anderen Datei importiert; bitte einen anderen Namen wählen</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; already exists in the project (tick overwrite to replace it)</source>
        <translation>%1: &apos;%2&apos; existiert bereits im Projekt (zum Ersetzen „Überschreiben“ ankreuzen)</translation>
    </message>
    <message>
        <source>Create or open a project first, then import recordings into it.</source>
        <translation>Zuerst ein Projekt anlegen oder öffnen, dann Aufnahmen hinein importieren.</translation>
    </message>
    <message>
        <source>Importing %1 file(s)…</source>
        <translation>%1 Datei(en) werden importiert …</translation>
    </message>
    <message>
        <source>Import cancelled; the project is unchanged.</source>
        <translation>Import abgebrochen; das Projekt ist unverändert.</translation>
    </message>
    <message>
        <source>Nothing was imported.

%1</source>
        <translation>Es wurde nichts importiert.

%1</translation>
    </message>
    <message>
        <source>%1: not in the roster %2</source>
        <translation>%1: nicht in der Kaderliste %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is in the roster but not among the files</source>
        <translation>%1: „%2“ steht in der Kaderliste, aber nicht unter den Dateien</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ImportWizardCheckPage</name>
    <message>
        <source>Check</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>Every file has been read without importing it. Fix the problems listed (go back to change the mapping or the names), then Finish imports all files at once.</source>
        <translation>Jede Datei wurde gelesen, ohne sie zu importieren. Die aufgeführten Probleme beheben (zurückgehen, um Zuordnung oder Namen zu ändern); dann importiert „Fertigstellen“ alle Dateien auf einmal.</translation>
    </message>
    <message>
        <source>Overwrite streams that exist in the project</source>
        <translation>Im Projekt vorhandene Datenströme überschreiben</translation>
    </message>
    <message>
        <source>Check Again</source>
        <translation>Erneut prüfen</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>Not checked yet.</source>
        <translation>Noch nicht geprüft.</translation>
    </message>
    <message>
        <source>All %1 file(s) can be imported.</source>
        <translation>Alle %1 Datei(en) können importiert werden.</translation>
    </message>
    <message>
        <source>%1 problem(s) must be fixed before importing.</source>
        <translation>%1 Problem(e) müssen vor dem Import behoben werden.</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ImportWizardFilesPage</name>
    <message>
        <source>Files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <source>Choose the files to import: several at once, or a folder with one file per athlete. Recording and athlete names can be edited here or on the next page.</source>
        <translation>Dateien für den Import wählen: mehrere auf einmal oder einen Ordner mit einer Datei pro Athlet. Namen von Aufnahme und Athlet lassen sich hier oder auf der nächsten Seite bearbeiten.</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufnahme</translation>
    </message>
    <message>
        <source>Athlete</source>
        <translation>Athlet</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Add Files…</source>
        <translation>Dateien hinzufügen …</translation>
    </message>
    <message>
        <source>Add Folder (One File per Athlete)…</source>
        <translation>Ordner hinzufügen (eine Datei pro Athlet) …</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Import Files</source>
        <translation>Dateien importieren</translation>
    </message>
    <message>
        <source>Folder with One File per Athlete</source>
        <translation>Ordner mit einer Datei pro Athlet</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>nicht lesbar</translation>
    </message>
    <message>
        <source>Apply Roster…</source>
        <translation>Kaderliste anwenden …</translation>
    </message>
    <message>
        <source>A CSV file,athlete,number,team,position,mass_kg naming the athlete of each file</source>
        <translation>Eine CSV-Datei file,athlete,number,team,position,mass_kg, die den Athleten jeder Datei nennt</translation>
    </message>
    <message>
        <source>Roster</source>
        <translation>Kaderliste</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV-Dateien (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message numerus="yes">
        <source>%n file(s) named from the roster.</source>
        <translation>
            <numerusform>%n Datei aus der Kaderliste benannt.</numerusform>
            <numerusform>%n Dateien aus der Kaderliste benannt.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>athlos::ui::ImportWizardMappingPage</name>
    <message>
        <source>Columns and Names</source>
        <translation>Spalten und Namen</translation>
    </message>
    <message>
        <source>Check each file: format, kind, the first rows, and which channel and unit each column becomes. Values are converted to SI units when imported.</source>
        <translation>Jede Datei prüfen: Format, Art, die ersten Zeilen und welcher Kanal mit welcher Einheit aus jeder Spalte wird. Beim Import werden die Werte in SI-Einheiten umgerechnet.</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>detect</source>
        <translation>erkennen</translation>
    </message>
    <message>
        <source>Format:</source>
        <translation>Format:</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation>Art:</translation>
    </message>
    <message>
        <source>Column</source>
        <translation>Spalte</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>Unit in File</source>
        <translation>Einheit in der Datei</translation>
    </message>
    <message>
        <source>Stored as</source>
        <translation>Gespeichert als</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>Time column:</source>
        <translation>Zeitspalte:</translation>
    </message>
    <message>
        <source>Recording:</source>
        <translation>Aufnahme:</translation>
    </message>
    <message>
        <source>Stream:</source>
        <translation>Datenstrom:</translation>
    </message>
    <message>
        <source>Athlete:</source>
        <translation>Athlet:</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>none (a table)</source>
        <translation>keine (eine Tabelle)</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Durations (s, ms, …), device uptime, Unix epochs (unix, unix_ms, unix_ns), ISO 8601 date-times, clock times (hh:mm:ss[.fff]) or Excel serial days</source>
        <translation>Dauern (s, ms, …), Gerätelaufzeit, Unix-Zeitstempel (unix, unix_ms, unix_ns), ISO-8601-Zeitpunkte, Uhrzeiten (hh:mm:ss[.fff]) oder Excel-Seriendatum</translation>
    </message>
    <message>
        <source>Unit or format:</source>
        <translation>Einheit oder Format:</translation>
    </message>
    <message>
        <source>YYYY-MM-DD, for clock times without a date</source>
        <translation>JJJJ-MM-TT, für Uhrzeiten ohne Datum</translation>
    </message>
    <message>
        <source>ISO 8601 UTC instant of t = 0, for relative times</source>
        <translation>ISO-8601-Zeitpunkt (UTC) von t = 0, für relative Zeiten</translation>
    </message>
    <message>
        <source>Start:</source>
        <translation>Beginn:</translation>
    </message>
    <message>
        <source>Date:</source>
        <translation>Datum:</translation>
    </message>
    <message>
        <source>A per-sample label column (numbers or text): runs of equal labels become annotations</source>
        <translation>Eine Label-Spalte pro Messwert (Zahlen oder Text): Folgen gleicher Labels werden zu Annotationen</translation>
    </message>
    <message>
        <source>names of number labels: 0=rest,1=run</source>
        <translation>Namen von Zahlen-Labels: 0=Ruhe,1=Laufen</translation>
    </message>
    <message>
        <source>Labels:</source>
        <translation>Labels:</translation>
    </message>
    <message>
        <source>Leave out columns that are neither mapped nor known to the kind</source>
        <translation>Spalten weglassen, die weder zugeordnet noch der Art bekannt sind</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>from the motion</source>
        <translation>aus der Bewegung</translation>
    </message>
    <message>
        <source>gaitmap files whose first column is a sample index: the sampling rate. Left at &quot;from the motion&quot;, it is estimated from the foot&apos;s rest phases and the import warns with the candidates&apos; scores (athlos import --rate)</source>
        <translation>gaitmap-Dateien, deren erste Spalte ein Probenindex ist: die Abtastrate. Bei „aus der Bewegung“ wird sie aus den Ruhephasen des Fußes geschätzt, und der Import warnt mit den Bewertungen der Kandidaten (athlos import --rate)</translation>
    </message>
    <message>
        <source>Sampling rate:</source>
        <translation>Abtastrate:</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ItemDescription</name>
    <message>
        <source>text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Sport</source>
        <translation>Sportart</translation>
    </message>
    <message>
        <source>Recordings</source>
        <translation>Aufnahmen</translation>
    </message>
    <message>
        <source>Streams</source>
        <translation>Datenströme</translation>
    </message>
    <message>
        <source>Created</source>
        <translation>Erstellt</translation>
    </message>
    <message>
        <source>Modified</source>
        <translation>Geändert</translation>
    </message>
    <message>
        <source>Written by</source>
        <translation>Geschrieben von</translation>
    </message>
    <message>
        <source>Tables</source>
        <translation>Tabellen</translation>
    </message>
    <message>
        <source>Annotations</source>
        <translation>Annotationen</translation>
    </message>
    <message>
        <source>Metadata</source>
        <translation>Metadaten</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Bezugssystem</translation>
    </message>
    <message>
        <source>Rows</source>
        <translation>Zeilen</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>%1 s to %2 s (%3 s)</source>
        <translation>%1 s bis %2 s (%3 s)</translation>
    </message>
    <message>
        <source>Columns</source>
        <translation>Spalten</translation>
    </message>
    <message>
        <source>Content hash</source>
        <translation>Inhalts-Hash</translation>
    </message>
    <message>
        <source>Attributes</source>
        <translation>Attribute</translation>
    </message>
    <message>
        <source>Provenance</source>
        <translation>Herkunft</translation>
    </message>
    <message>
        <source>Processor</source>
        <translation>Prozessor</translation>
    </message>
    <message>
        <source>Imported with</source>
        <translation>Importiert mit</translation>
    </message>
    <message>
        <source>Source file</source>
        <translation>Quelldatei</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingaben</translation>
    </message>
    <message>
        <source>App version</source>
        <translation>App-Version</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>%1: %2, %3 rows</source>
        <translation>%1: %2, %3 Zeilen</translation>
    </message>
    <message>
        <source>Result of %1 %2 from %3</source>
        <translation>Ergebnis von %1 %2 aus %3</translation>
    </message>
    <message>
        <source>Parameters: %1</source>
        <translation>Parameter: %1</translation>
    </message>
    <message>
        <source>Athlos %1, %2</source>
        <translation>Athlos %1, %2</translation>
    </message>
    <message>
        <source>Imported from %1</source>
        <translation>Importiert aus %1</translation>
    </message>
    <message>
        <source>%1: table %2, %3 rows</source>
        <translation>%1: Tabelle %2, %3 Zeilen</translation>
    </message>
    <message>
        <source>Result of %1 %2</source>
        <translation>Ergebnis von %1 %2</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Werte</translation>
    </message>
</context>
<context>
    <name>athlos::ui::JointAnglesView</name>
    <message>
        <source>flexion [°]</source>
        <translation>Flexion [°]</translation>
    </message>
    <message>
        <source>abduction [°]</source>
        <translation>Abduktion [°]</translation>
    </message>
    <message>
        <source>internal rotation [°]</source>
        <translation>Innenrotation [°]</translation>
    </message>
    <message>
        <source>Stream:</source>
        <translation>Datenstrom:</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a joint-angles stream (flexion, abduction, rotation)</source>
        <translation>&apos;%1&apos; ist kein Gelenkwinkel-Datenstrom (flexion, abduction, rotation)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <source>reference (RMSE %1°)</source>
        <translation>Referenz (RMSE %1°)</translation>
    </message>
    <message>
        <source>No reference angles for this joint in the recording.</source>
        <translation>Keine Referenzwinkel für dieses Gelenk in der Aufnahme.</translation>
    </message>
    <message>
        <source>Reference: %1</source>
        <translation>Referenz: %1</translation>
    </message>
    <message>
        <source>No joint-angles stream in this project; run joint-angles first.</source>
        <translation>Kein Gelenkwinkel-Datenstrom in diesem Projekt; zuerst joint-angles ausführen.</translation>
    </message>
    <message>
        <source>t = %1 s: flexion %2°, abduction %3°, rotation %4°</source>
        <translation>t = %1 s: Flexion %2°, Abduktion %3°, Rotation %4°</translation>
    </message>
    <message>
        <source>Other side</source>
        <translation>Andere Seite</translation>
    </message>
    <message>
        <source>Overlay the same joint of the other side (left/right comparison)</source>
        <translation>Dasselbe Gelenk der anderen Seite überlagern (Links-rechts-Vergleich)</translation>
    </message>
</context>
<context>
    <name>athlos::ui::LpsCalibrationWizard</name>
    <message>
        <source>Calibrate LPS</source>
        <translation>LPS kalibrieren</translation>
    </message>
    <message>
        <source>Initial beacon positions</source>
        <translation>Anfängliche Bakenpositionen</translation>
    </message>
    <message>
        <source>Rough positions (a few metres are fine) from the project or a CSV file (id, x, y, z).</source>
        <translation>Grobe Positionen (einige Meter Abweichung genügen) aus dem Projekt oder einer CSV-Datei (id, x, y, z).</translation>
    </message>
    <message>
        <source>Import CSV…</source>
        <translation>CSV importieren…</translation>
    </message>
    <message>
        <source>Beacon table:</source>
        <translation>Bakentabelle:</translation>
    </message>
    <message>
        <source>Venue drawing:</source>
        <translation>Anlagenzeichnung:</translation>
    </message>
    <message>
        <source>Import beacon table</source>
        <translation>Bakentabelle importieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt)</source>
        <translation>CSV-Dateien (*.csv *.txt)</translation>
    </message>
    <message>
        <source>initial</source>
        <translation>anfänglich</translation>
    </message>
    <message>
        <source>Calibration walk</source>
        <translation>Kalibrierlauf</translation>
    </message>
    <message>
        <source>The TDoA recording of the walk and the calibration settings. Next runs the calibration.</source>
        <translation>Die TDoA-Aufzeichnung des Kalibrierlaufs und die Kalibriereinstellungen. „Weiter“ startet die Kalibrierung.</translation>
    </message>
    <message>
        <source>Show the walk positions (runs lps-positioning with the calibrated beacons)</source>
        <translation>Positionen des Laufs anzeigen (führt lps-positioning mit den kalibrierten Baken aus)</translation>
    </message>
    <message>
        <source>TDoA stream:</source>
        <translation>TDoA-Datenstrom:</translation>
    </message>
    <message>
        <source>Output (rec/table):</source>
        <translation>Ausgabe (Aufnahme/Tabelle):</translation>
    </message>
    <message>
        <source>The lps-calibration processor was not found; check the plugin folder.</source>
        <translation>Der Prozessor lps-calibration wurde nicht gefunden; bitte den Plugin-Ordner prüfen.</translation>
    </message>
    <message>
        <source>Calibration result</source>
        <translation>Kalibrierergebnis</translation>
    </message>
    <message>
        <source>Next keeps the result; Retry discards it so you can change the settings.</source>
        <translation>„Weiter“ behält das Ergebnis; „Erneut versuchen“ verwirft es, damit Sie die Einstellungen ändern können.</translation>
    </message>
    <message>
        <source>RMS residual [m]</source>
        <translation>RMS-Residuum [m]</translation>
    </message>
    <message>
        <source>Retry with other settings</source>
        <translation>Erneut versuchen mit anderen Einstellungen</translation>
    </message>
    <message>
        <source>Align and save</source>
        <translation>Ausrichten und speichern</translation>
    </message>
    <message>
        <source>Optionally move the beacons so that surveyed venue marks land on their known coordinates.</source>
        <translation>Optional die Baken so verschieben, dass vermessene Markierungen der Anlage auf ihren bekannten Koordinaten liegen.</translation>
    </message>
    <message>
        <source>Align to venue marks (lps-align)</source>
        <translation>An Markierungen der Anlage ausrichten (lps-align)</translation>
    </message>
    <message>
        <source>Marks:</source>
        <translation>Markierungen:</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>Modus:</translation>
    </message>
    <message>
        <source>Save as (rec/table):</source>
        <translation>Speichern als (Aufnahme/Tabelle):</translation>
    </message>
    <message>
        <source>Choose the TDoA stream of the calibration walk.</source>
        <translation>Wählen Sie den TDoA-Datenstrom des Kalibrierlaufs.</translation>
    </message>
    <message>
        <source>The output must be named rec/table.</source>
        <translation>Die Ausgabe muss Aufnahme/Tabelle heißen.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; already exists; choose another name.</source>
        <translation>„%1“ existiert bereits; wählen Sie einen anderen Namen.</translation>
    </message>
    <message>
        <source>calibrated</source>
        <translation>kalibriert</translation>
    </message>
    <message>
        <source>nRMSR before: %1 m, after: %2 m; %3 fixes used, %4 removed; converged: %5</source>
        <translation>nRMSR vorher: %1 m, nachher: %2 m; %3 Positionen verwendet, %4 entfernt; konvergiert: %5</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>There is no calibration result to save.</source>
        <translation>Es gibt kein Kalibrierergebnis zum Speichern.</translation>
    </message>
    <message>
        <source>The name must be rec/table.</source>
        <translation>Der Name muss Aufnahme/Tabelle lauten.</translation>
    </message>
    <message>
        <source>The aligned table needs a name of its own.</source>
        <translation>Die ausgerichtete Tabelle braucht einen eigenen Namen.</translation>
    </message>
</context>
<context>
    <name>athlos::ui::MainWindow</name>
    <message>
        <source>Time series</source>
        <translation>Zeitreihen</translation>
    </message>
    <message>
        <source>Trajectory</source>
        <translation>Trajektorie</translation>
    </message>
    <message>
        <source>Open a project, or drop recordings onto the window to import them.</source>
        <translation>Öffnen Sie ein Projekt oder ziehen Sie Aufnahmen in das Fenster, um sie zu importieren.</translation>
    </message>
    <message>
        <source>&amp;New Project…</source>
        <translation>&amp;Neues Projekt…</translation>
    </message>
    <message>
        <source>Create an empty project file</source>
        <translation>Eine leere Projektdatei anlegen</translation>
    </message>
    <message>
        <source>&amp;Open Project…</source>
        <translation>Projekt ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Open an existing project file</source>
        <translation>Eine vorhandene Projektdatei öffnen</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the project (the file is replaced atomically)</source>
        <translation>Das Projekt speichern (die Datei wird atomar ersetzt)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Save the project under a new name</source>
        <translation>Das Projekt unter einem neuen Namen speichern</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importieren…</translation>
    </message>
    <message>
        <source>Import recordings (CSV, BROAD, gaitmap, …) into the project</source>
        <translation>Aufnahmen (CSV, BROAD, gaitmap, …) in das Projekt importieren</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;About Athlos</source>
        <translation>Ü&amp;ber Athlos</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <source>Creating project…</source>
        <translation>Projekt wird angelegt…</translation>
    </message>
    <message>
        <source>Could not create the project</source>
        <translation>Das Projekt konnte nicht angelegt werden</translation>
    </message>
    <message>
        <source>Created %1</source>
        <translation>%1 angelegt</translation>
    </message>
    <message>
        <source>Could not open the project</source>
        <translation>Das Projekt konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Saving…</source>
        <translation>Wird gespeichert…</translation>
    </message>
    <message>
        <source>Saving cancelled; the file on disk is unchanged.</source>
        <translation>Speichern abgebrochen; die Datei auf dem Datenträger ist unverändert.</translation>
    </message>
    <message>
        <source>Could not save the project</source>
        <translation>Das Projekt konnte nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Saving cancelled; nothing was written.</source>
        <translation>Speichern abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Create or open a project first, then import recordings into it.</source>
        <translation>Legen Sie zuerst ein Projekt an oder öffnen Sie eines, und importieren Sie dann Aufnahmen hinein.</translation>
    </message>
    <message>
        <source>Import cancelled; the project is unchanged.</source>
        <translation>Import abgebrochen; das Projekt ist unverändert.</translation>
    </message>
    <message>
        <source>Import failed</source>
        <translation>Import fehlgeschlagen</translation>
    </message>
    <message>
        <source>Nothing was imported.

%1</source>
        <translation>Es wurde nichts importiert.

%1</translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>%1 importiert</translation>
    </message>
    <message>
        <source>Import warnings</source>
        <translation>Warnungen beim Import</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The project %1 has unsaved changes. Save them?</source>
        <translation>Das Projekt %1 hat ungespeicherte Änderungen. Sollen sie gespeichert werden?</translation>
    </message>
    <message>
        <source>New Project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message>
        <source>Athlos projects (*.athlos)</source>
        <translation>Athlos-Projekte (*.athlos)</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <source>Athlos projects (*.athlos);;All files (*)</source>
        <translation>Athlos-Projekte (*.athlos);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <source>Recordings (%1)</source>
        <translation>Aufnahmen (%1)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Import Recordings</source>
        <translation>Aufnahmen importieren</translation>
    </message>
    <message>
        <source>No recent projects</source>
        <translation>Keine zuletzt geöffneten Projekte</translation>
    </message>
    <message>
        <source>Clear List</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <source>About Athlos</source>
        <translation>Über Athlos</translation>
    </message>
    <message>
        <source>Analysis of sports recordings from local positioning systems, IMUs and GNSS.</source>
        <translation>Analyse von Sportaufnahmen aus lokalen Positionierungssystemen, IMUs und GNSS.</translation>
    </message>
    <message>
        <source>Built with:</source>
        <translation>Erstellt mit:</translation>
    </message>
    <message>
        <source>Athlos</source>
        <translation>Athlos</translation>
    </message>
    <message>
        <source>%1[*] — Athlos</source>
        <translation>%1[*] — Athlos</translation>
    </message>
    <message>
        <source>Importing 1 file…</source>
        <translation>1 Datei wird importiert…</translation>
    </message>
    <message>
        <source>Importing %1 files…</source>
        <translation>%1 Dateien werden importiert…</translation>
    </message>
    <message>
        <source>&amp;Run Processor…</source>
        <translation>Prozessor &amp;ausführen…</translation>
    </message>
    <message>
        <source>Run any processor on streams of the project</source>
        <translation>Einen beliebigen Prozessor auf Datenströme des Projekts anwenden</translation>
    </message>
    <message>
        <source>Add &amp;Time-Series Panel</source>
        <translation>&amp;Zeitreihen-Ansicht hinzufügen</translation>
    </message>
    <message>
        <source>Plot the selected stream in another panel that shares the time cursor</source>
        <translation>Den gewählten Datenstrom in einer weiteren Ansicht mit gemeinsamem Zeitcursor zeigen</translation>
    </message>
    <message>
        <source>Select a stream first.</source>
        <translation>Wählen Sie zuerst einen Datenstrom.</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Annotate Mode</source>
        <translation>&amp;Annotationsmodus</translation>
    </message>
    <message>
        <source>Drag on the plot to create intervals of the current class (Shift+drag works always)</source>
        <translation>Ziehen im Diagramm legt Intervalle der aktuellen Klasse an (Umschalt+Ziehen geht immer)</translation>
    </message>
    <message>
        <source>Add Annotation &amp;Class…</source>
        <translation>Annotations&amp;klasse hinzufügen…</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen…</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Annotator name:</source>
        <translation>Name des Annotierenden:</translation>
    </message>
    <message>
        <source>&amp;Export View…</source>
        <translation>Ansicht e&amp;xportieren…</translation>
    </message>
    <message>
        <source>Save the shown plot as PNG, SVG or PDF</source>
        <translation>Das gezeigte Diagramm als PNG, SVG oder PDF speichern</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Show &amp;All</source>
        <translation>&amp;Alles zeigen</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Processing</source>
        <translation>&amp;Verarbeitung</translation>
    </message>
    <message>
        <source>Open a project first.</source>
        <translation>Öffnen Sie zuerst ein Projekt.</translation>
    </message>
    <message>
        <source>Another job is still running.</source>
        <translation>Eine andere Aufgabe läuft noch.</translation>
    </message>
    <message>
        <source>Unknown processor &apos;%1&apos;.</source>
        <translation>Unbekannter Prozessor „%1“.</translation>
    </message>
    <message>
        <source>Running %1…</source>
        <translation>%1 läuft…</translation>
    </message>
    <message>
        <source>%1 cancelled; the project is unchanged.</source>
        <translation>%1 abgebrochen; das Projekt ist unverändert.</translation>
    </message>
    <message>
        <source>Cancelled; the project is unchanged.</source>
        <translation>Abgebrochen; das Projekt ist unverändert.</translation>
    </message>
    <message>
        <source>The processor did not run.</source>
        <translation>Der Prozessor wurde nicht ausgeführt.</translation>
    </message>
    <message>
        <source>%1 wrote %2</source>
        <translation>%1 hat %2 geschrieben</translation>
    </message>
    <message>
        <source>Re-run</source>
        <translation>Erneut ausführen</translation>
    </message>
    <message>
        <source>The processor &apos;%1&apos; is not available (is its plugin installed?).</source>
        <translation>Der Prozessor „%1“ ist nicht verfügbar (ist sein Plugin installiert?).</translation>
    </message>
    <message>
        <source>Re-run with Changed Parameters…</source>
        <translation>Mit geänderten Parametern erneut ausführen…</translation>
    </message>
    <message>
        <source>Annotations</source>
        <translation>Annotationen</translation>
    </message>
    <message>
        <source>Autosave failed: %1 (the journal keeps your edits)</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1 (das Journal bewahrt Ihre Änderungen)</translation>
    </message>
    <message>
        <source>Autosaved</source>
        <translation>Automatisch gespeichert</translation>
    </message>
    <message>
        <source>Recover annotations</source>
        <translation>Annotationen wiederherstellen</translation>
    </message>
    <message>
        <source>%1 has annotation edits that were not saved (the program ended unexpectedly). Recover them?</source>
        <translation>%1 hat ungespeicherte Annotationsänderungen (das Programm wurde unerwartet beendet). Wiederherstellen?</translation>
    </message>
    <message>
        <source>Could not recover annotations</source>
        <translation>Annotationen konnten nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <source>Annotation edits recovered from the journal: %1</source>
        <translation>Aus dem Journal wiederhergestellte Annotationsänderungen: %1</translation>
    </message>
    <message>
        <source>Export View…</source>
        <translation>Ansicht exportieren…</translation>
    </message>
    <message>
        <source>Opened after an interrupted save</source>
        <translation>Nach einem unterbrochenen Speichern geöffnet</translation>
    </message>
</context>
<context>
    <name>athlos::ui::OrientationAnglesView</name>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>angle [°]</source>
        <translation>Winkel [°]</translation>
    </message>
    <message>
        <source>error [°]</source>
        <translation>Fehler [°]</translation>
    </message>
    <message>
        <source>Stream:</source>
        <translation>Datenstrom:</translation>
    </message>
    <message>
        <source>Sequence:</source>
        <translation>Reihenfolge:</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an orientation stream (qw, qx, qy, qz)</source>
        <translation>„%1“ ist kein Orientierungsdatenstrom (qw, qx, qy, qz)</translation>
    </message>
    <message>
        <source>yaw (Z)</source>
        <translation>Gieren (Z)</translation>
    </message>
    <message>
        <source>pitch (Y)</source>
        <translation>Nicken (Y)</translation>
    </message>
    <message>
        <source>roll (X)</source>
        <translation>Rollen (X)</translation>
    </message>
    <message>
        <source>angle 1 (%1)</source>
        <translation>Winkel 1 (%1)</translation>
    </message>
    <message>
        <source>angle 2 (%1)</source>
        <translation>Winkel 2 (%1)</translation>
    </message>
    <message>
        <source>angle 3 (%1)</source>
        <translation>Winkel 3 (%1)</translation>
    </message>
    <message>
        <source>total (RMS %1°)</source>
        <translation>gesamt (RMS %1°)</translation>
    </message>
    <message>
        <source>heading (RMS %1°)</source>
        <translation>Kurs (RMS %1°)</translation>
    </message>
    <message>
        <source>inclination (RMS %1°)</source>
        <translation>Neigung (RMS %1°)</translation>
    </message>
    <message>
        <source>Error against %1 (%2 samples).</source>
        <translation>Fehler gegenüber %1 (%2 Abtastwerte).</translation>
    </message>
    <message>
        <source>No reference orientation (kind reference with qw..qz) in this recording.</source>
        <translation>Keine Referenzorientierung (Art reference mit qw..qz) in dieser Aufnahme.</translation>
    </message>
    <message>
        <source>Orientation angles</source>
        <translation>Orientierungswinkel</translation>
    </message>
    <message>
        <source>no orientation stream (kind orientation with qw, qx, qy, qz) in this project; run orientation first</source>
        <translation>kein Orientierungsdatenstrom (Art orientation mit qw, qx, qy, qz) in diesem Projekt; zuerst orientation ausführen</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Orientierung</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ParameterForm</name>
    <message>
        <source>(not set)</source>
        <translation>(nicht gesetzt)</translation>
    </message>
    <message>
        <source>This processor has no parameters.</source>
        <translation>Dieser Prozessor hat keine Parameter.</translation>
    </message>
    <message>
        <source>Set %1 (otherwise the processor decides)</source>
        <translation>%1 setzen (sonst entscheidet der Prozessor)</translation>
    </message>
</context>
<context>
    <name>athlos::ui::PlaybackCanvas</name>
    <message>
        <source>speed [m/s]</source>
        <translation>Geschwindigkeit [m/s]</translation>
    </message>
</context>
<context>
    <name>athlos::ui::PlaybackView</name>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <source>Frame the venue again (or double-click the view).</source>
        <translation>Die Sportstätte wieder einpassen (oder Doppelklick in die Ansicht).</translation>
    </message>
    <message>
        <source>Recording:</source>
        <translation>Aufnahme:</translation>
    </message>
    <message>
        <source>Venue:</source>
        <translation>Sportstätte:</translation>
    </message>
    <message>
        <source>Trail:</source>
        <translation>Spur:</translation>
    </message>
    <message>
        <source>no recording &apos;%1&apos; in this project</source>
        <translation>keine Aufnahme &apos;%1&apos; in diesem Projekt</translation>
    </message>
    <message>
        <source>recording &apos;%1&apos; has no position stream (lps-position, trajectory or gnss with x, y)</source>
        <translation>Aufnahme &apos;%1&apos; hat keinen Positionsstrom (lps-position, trajectory oder gnss mit x, y)</translation>
    </message>
    <message numerus="yes">
        <source>%n athlete(s)</source>
        <translation>
            <numerusform>%n Athlet</numerusform>
            <numerusform>%n Athleten</numerusform>
        </translation>
    </message>
    <message>
        <source>Pitch &apos;%1&apos; %2 × %3 m</source>
        <translation>Feld &apos;%1&apos; %2 × %3 m</translation>
    </message>
</context>
<context>
    <name>athlos::ui::PlotExporter</name>
    <message>
        <source>Nothing to export.</source>
        <translation>Nichts zu exportieren.</translation>
    </message>
    <message>
        <source>Unknown export format &apos;%1&apos;; use .png, .svg or .pdf.</source>
        <translation>Unbekanntes Exportformat „%1“; verwenden Sie .png, .svg oder .pdf.</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG-Zeichnung (*.svg)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <source>Export View</source>
        <translation>Ansicht exportieren</translation>
    </message>
</context>
<context>
    <name>athlos::ui::PositionFilterWizard</name>
    <message>
        <source>Filter positions</source>
        <translation>Positionen filtern</translation>
    </message>
    <message>
        <source>Position stream</source>
        <translation>Positionsdatenstrom</translation>
    </message>
    <message>
        <source>The LPS fixes (kind lps-position, columns x and y) to filter.</source>
        <translation>Die zu filternden LPS-Positionen (Art lps-position, Spalten x und y).</translation>
    </message>
    <message>
        <source>Stream:</source>
        <translation>Datenstrom:</translation>
    </message>
    <message>
        <source>This project has no lps-position stream; import one first.</source>
        <translation>Dieses Projekt hat keinen lps-position-Datenstrom; importieren Sie zuerst einen.</translation>
    </message>
    <message>
        <source>Track and pose</source>
        <translation>Bahn und Lage</translation>
    </message>
    <message>
        <source>Place the track over the raw positions: the track models follow its lanes.</source>
        <translation>Legen Sie die Bahn über die Rohpositionen: Die Bahnmodelle folgen ihren Bahnen.</translation>
    </message>
    <message>
        <source>Fit pose</source>
        <translation>Lage anpassen</translation>
    </message>
    <message>
        <source>Centre the track on the positions and turn it along their longest extent.</source>
        <translation>Die Bahn auf die Positionen zentrieren und entlang ihrer größten Ausdehnung drehen.</translation>
    </message>
    <message>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
    <message>
        <source>Track:</source>
        <translation>Bahn:</translation>
    </message>
    <message>
        <source>Origin x:</source>
        <translation>Ursprung x:</translation>
    </message>
    <message>
        <source>Origin y:</source>
        <translation>Ursprung y:</translation>
    </message>
    <message>
        <source>Rotation:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <source>Filter and noise</source>
        <translation>Filter und Rauschen</translation>
    </message>
    <message>
        <source>Kalman filter variant, motion model and noise settings.</source>
        <translation>Kalman-Filter-Variante, Bewegungsmodell und Rauscheinstellungen.</translation>
    </message>
    <message>
        <source>Filter:</source>
        <translation>Filter:</translation>
    </message>
    <message>
        <source>Motion model:</source>
        <translation>Bewegungsmodell:</translation>
    </message>
    <message>
        <source>Noise:</source>
        <translation>Rauschen:</translation>
    </message>
    <message>
        <source>The position-filter processor was not found; check the plugin folder.</source>
        <translation>Der Prozessor position-filter wurde nicht gefunden; bitte den Plugin-Ordner prüfen.</translation>
    </message>
    <message>
        <source>Smoothing and output</source>
        <translation>Glättung und Ausgabe</translation>
    </message>
    <message>
        <source>Next runs the filter.</source>
        <translation>„Weiter“ startet den Filter.</translation>
    </message>
    <message>
        <source>Resample to a uniform rate</source>
        <translation>Auf eine gleichmäßige Rate umtasten</translation>
    </message>
    <message>
        <source>Smoother:</source>
        <translation>Glätter:</translation>
    </message>
    <message>
        <source>Lag:</source>
        <translation>Verzögerung:</translation>
    </message>
    <message>
        <source>Output (rec/stream):</source>
        <translation>Ausgabe (Aufnahme/Datenstrom):</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>The output must be named rec/stream.</source>
        <translation>Die Ausgabe muss Aufnahme/Datenstrom heißen.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; already exists; choose another name.</source>
        <translation>„%1“ existiert bereits; wählen Sie einen anderen Namen.</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ProcessorDialog</name>
    <message>
        <source>Run Processor</source>
        <translation>Prozessor ausführen</translation>
    </message>
    <message>
        <source>Inputs and output</source>
        <translation>Eingaben und Ausgabe</translation>
    </message>
    <message>
        <source>Output:</source>
        <translation>Ausgabe:</translation>
    </message>
    <message>
        <source>recording/name</source>
        <translation>aufnahme/name</translation>
    </message>
    <message>
        <source>Where the result is stored, as recording/name</source>
        <translation>Wo das Ergebnis gespeichert wird, als aufnahme/name</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Processor:</source>
        <translation>Prozessor:</translation>
    </message>
    <message>
        <source>No processors were found. Check the plugin folder (ATHLOS_PLUGIN_PATH).</source>
        <translation>Keine Prozessoren gefunden. Prüfen Sie den Plugin-Ordner (ATHLOS_PLUGIN_PATH).</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Choose a processor.</source>
        <translation>Wählen Sie einen Prozessor.</translation>
    </message>
    <message>
        <source>Open a project first.</source>
        <translation>Öffnen Sie zuerst ein Projekt.</translation>
    </message>
    <message>
        <source>The output name must be recording/name, e.g. run1/imu-100hz.</source>
        <translation>Der Ausgabename muss aufnahme/name lauten, z. B. run1/imu-100hz.</translation>
    </message>
    <message>
        <source>Input &apos;%1&apos; needs a stream of kind %2; the project has none.</source>
        <translation>Eingabe „%1“ braucht einen Datenstrom der Art %2; das Projekt hat keinen.</translation>
    </message>
</context>
<context>
    <name>athlos::ui::ProjectTreeModel</name>
    <message>
        <source>recording</source>
        <translation>Aufnahme</translation>
    </message>
    <message>
        <source>Recording %1</source>
        <translation>Aufnahme %1</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>Rows</source>
        <translation>Zeilen</translation>
    </message>
    <message>
        <source>Columns</source>
        <translation>Spalten</translation>
    </message>
    <message>
        <source>1 item</source>
        <translation>1 Eintrag</translation>
    </message>
    <message>
        <source>%1 items</source>
        <translation>%1 Einträge</translation>
    </message>
</context>
<context>
    <name>athlos::ui::SessionReport</name>
    <message>
        <source>Athlos session report</source>
        <translation>Athlos-Einheitsbericht</translation>
    </message>
    <message>
        <source>Session report: %1</source>
        <translation>Einheitsbericht: %1</translation>
    </message>
    <message>
        <source>%1 · %2 athletes · generated %3 by Athlos</source>
        <translation>%1 · %2 Athleten · erstellt %3 von Athlos</translation>
    </message>
    <message>
        <source>Athlete</source>
        <translation>Athlet</translation>
    </message>
    <message>
        <source>Distance m</source>
        <translation>Distanz m</translation>
    </message>
    <message>
        <source>Max km/h</source>
        <translation>Max. km/h</translation>
    </message>
    <message>
        <source>HSR m</source>
        <translation>HSR m</translation>
    </message>
    <message>
        <source>Sprints</source>
        <translation>Sprints</translation>
    </message>
    <message>
        <source>Acc</source>
        <translation>Beschl.</translation>
    </message>
    <message>
        <source>Dec</source>
        <translation>Verz.</translation>
    </message>
    <message>
        <source>Peak 1 min m</source>
        <translation>Spitze 1 min m</translation>
    </message>
    <message>
        <source>Met. W/kg</source>
        <translation>Met. W/kg</translation>
    </message>
    <message>
        <source>distance (m)</source>
        <translation>Distanz (m)</translation>
    </message>
    <message>
        <source>%1 · distance %2 m in %3 min · max speed %4 km/h · HSR %5 m · sprints %6 · accelerations %7 · decelerations %8 · metabolic power %9 W/kg</source>
        <translation>%1 · Distanz %2 m in %3 min · Höchstgeschwindigkeit %4 km/h · HSR %5 m · Sprints %6 · Beschleunigungen %7 · Verzögerungen %8 · metabolische Leistung %9 W/kg</translation>
    </message>
    <message>
        <source>speed zone (km/h)</source>
        <translation>Geschwindigkeitszone (km/h)</translation>
    </message>
    <message>
        <source>Period</source>
        <translation>Abschnitt</translation>
    </message>
    <message>
        <source>Start min</source>
        <translation>Beginn min</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Actions: %1</source>
        <translation>Aktionen: %1</translation>
    </message>
</context>
<context>
    <name>athlos::ui::StickFigureView</name>
    <message>
        <source>No body-com result in this project; run body-com first.</source>
        <translation>Kein body-com-Ergebnis in diesem Projekt; führen Sie zuerst body-com aus.</translation>
    </message>
    <message>
        <source>Follow the pelvis heading</source>
        <translation>Der Beckenausrichtung folgen</translation>
    </message>
    <message>
        <source>Joints:</source>
        <translation>Gelenke:</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a body-com joint stream (joint-centres relative to the lumbar joint)</source>
        <translation>„%1“ ist kein body-com-Gelenkdatenstrom (Gelenkzentren relativ zum Lumbalgelenk)</translation>
    </message>
    <message>
        <source>No body-com joint stream.</source>
        <translation>Kein body-com-Gelenkdatenstrom.</translation>
    </message>
    <message>
        <source>t = %1 s: CoM %2, %3, %4 mm from the lumbar joint (E, N, up); fore-aft %5 mm</source>
        <translation>t = %1 s: KSP %2, %3, %4 mm vom Lumbalgelenk (O, N, oben); vorn–hinten %5 mm</translation>
    </message>
    <message>
        <source>t = %1 s (no centre-of-mass stream beside the joints)</source>
        <translation>t = %1 s (kein Schwerpunkt-Datenstrom neben den Gelenken)</translation>
    </message>
</context>
<context>
    <name>athlos::ui::TimeSeriesPanel</name>
    <message>
        <source>Columns</source>
        <translation>Spalten</translation>
    </message>
    <message>
        <source>Choose the columns to plot</source>
        <translation>Darzustellende Spalten wählen</translation>
    </message>
    <message>
        <source>Fit y to visible range</source>
        <translation>y an sichtbaren Bereich anpassen</translation>
    </message>
    <message>
        <source>Full range</source>
        <translation>Gesamter Bereich</translation>
    </message>
    <message>
        <source>Show the whole recording (double-click the plot does the same)</source>
        <translation>Die ganze Aufnahme zeigen (ein Doppelklick in den Plot bewirkt dasselbe)</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>%1 — could not load: %2</source>
        <translation>%1 — konnte nicht geladen werden: %2</translation>
    </message>
    <message>
        <source>%1 — loading…</source>
        <translation>%1 — wird geladen…</translation>
    </message>
    <message>
        <source>%1 — %2 samples</source>
        <translation>%1 — %2 Messwerte</translation>
    </message>
    <message>
        <source>Select a stream in the project tree to plot it.</source>
        <translation>Wählen Sie im Projektbaum einen Datenstrom aus, um ihn darzustellen.</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>at cursor</source>
        <translation>am Cursor</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>Mittel</translation>
    </message>
    <message>
        <source>SD</source>
        <translation>SA</translation>
    </message>
    <message>
        <source>min</source>
        <translation>Min.</translation>
    </message>
    <message>
        <source>max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>Clock time</source>
        <translation>Uhrzeit</translation>
    </message>
    <message>
        <source>Label the time axis with the time of day (UTC) the file gives, instead of seconds since the first sample</source>
        <translation>Die Zeitachse mit der Uhrzeit (UTC) aus der Datei beschriften statt mit Sekunden seit dem ersten Messwert</translation>
    </message>
    <message>
        <source>time of day</source>
        <translation>Uhrzeit</translation>
    </message>
    <message>
        <source>time of day (UTC)</source>
        <translation>Uhrzeit (UTC)</translation>
    </message>
</context>
<context>
    <name>athlos::ui::TrackTrajectoryView</name>
    <message>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
    <message>
        <source>Raw positions</source>
        <translation>Rohpositionen</translation>
    </message>
    <message>
        <source>Filtered trajectory</source>
        <translation>Gefilterte Trajektorie</translation>
    </message>
    <message>
        <source>Outliers</source>
        <translation>Ausreißer</translation>
    </message>
    <message>
        <source>speed [m/s]</source>
        <translation>Geschwindigkeit [m/s]</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a stream of this project</source>
        <translation>„%1“ ist kein Datenstrom dieses Projekts</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has no x/y samples</source>
        <translation>„%1“ hat keine x/y-Abtastwerte</translation>
    </message>
    <message>
        <source>%1: %2 filtered samples, %3 raw fixes, %4 rejected as outliers</source>
        <translation>%1: %2 gefilterte Abtastwerte, %3 Rohpositionen, %4 als Ausreißer verworfen</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>no position-filter result (kind trajectory) in this project; run position-filter first</source>
        <translation>kein Ergebnis von position-filter (Art trajectory) in diesem Projekt; zuerst position-filter ausführen</translation>
    </message>
    <message>
        <source>Track</source>
        <translation>Bahn</translation>
    </message>
</context>
<context>
    <name>athlos::ui::TrainClassifierWizard</name>
    <message>
        <source>%1 windows from %2 recordings, %3 features, classes: %4
</source>
        <translation>%1 Fenster aus %2 Aufnahmen, %3 Merkmale, Klassen: %4
</translation>
    </message>
    <message>
        <source>Train classifier</source>
        <translation>Klassifikator trainieren</translation>
    </message>
    <message>
        <source>Recordings and classes</source>
        <translation>Aufnahmen und Klassen</translation>
    </message>
    <message>
        <source>Recordings with the stream and ground-truth annotations (manual or imported) to learn from, and the labels to learn.</source>
        <translation>Aufnahmen mit dem Datenstrom und Referenz-Annotationen (manuell oder importiert), aus denen gelernt wird, und die zu lernenden Bezeichnungen.</translation>
    </message>
    <message>
        <source>Stream:</source>
        <translation>Datenstrom:</translation>
    </message>
    <message>
        <source>Recordings:</source>
        <translation>Aufnahmen:</translation>
    </message>
    <message>
        <source>Classes:</source>
        <translation>Klassen:</translation>
    </message>
    <message>
        <source>Windows and classifier</source>
        <translation>Fenster und Klassifikator</translation>
    </message>
    <message>
        <source>Sliding windows for continuous activities, or windows around detected events for discrete actions; the classifier and how it is cross-validated.</source>
        <translation>Gleitende Fenster für andauernde Aktivitäten oder Fenster um erkannte Ereignisse für einzelne Aktionen; der Klassifikator und seine Kreuzvalidierung.</translation>
    </message>
    <message>
        <source>Window:</source>
        <translation>Fenster:</translation>
    </message>
    <message>
        <source>Step:</source>
        <translation>Schritt:</translation>
    </message>
    <message>
        <source>Segmentation:</source>
        <translation>Segmentierung:</translation>
    </message>
    <message>
        <source>Classifier:</source>
        <translation>Klassifikator:</translation>
    </message>
    <message>
        <source>Cross-validation:</source>
        <translation>Kreuzvalidierung:</translation>
    </message>
    <message>
        <source>Cross-validation</source>
        <translation>Kreuzvalidierung</translation>
    </message>
    <message>
        <source>Trained on a worker; the confusion matrix shows the share of each annotated class (rows) predicted as each class (columns).</source>
        <translation>Im Hintergrund trainiert; die Konfusionsmatrix zeigt den Anteil jeder annotierten Klasse (Zeilen), der als jede Klasse (Spalten) vorhergesagt wurde.</translation>
    </message>
    <message>
        <source>Cancel training</source>
        <translation>Training abbrechen</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>The model trained on every window is stored in the project; classify with Processing → Classify actions.</source>
        <translation>Das auf allen Fenstern trainierte Modell wird im Projekt gespeichert; klassifizieren mit Verarbeitung → Aktionen klassifizieren.</translation>
    </message>
    <message>
        <source>Model name:</source>
        <translation>Modellname:</translation>
    </message>
    <message>
        <source>Training…</source>
        <translation>Training…</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>predicted</source>
        <translation>vorhergesagt</translation>
    </message>
    <message>
        <source>annotated</source>
        <translation>annotiert</translation>
    </message>
    <message>
        <source>There is no trained model to save.</source>
        <translation>Es gibt kein trainiertes Modell zum Speichern.</translation>
    </message>
    <message>
        <source>Give the model a name without &apos;/&apos;.</source>
        <translation>Geben Sie dem Modell einen Namen ohne &apos;/&apos;.</translation>
    </message>
    <message>
        <source>the %1 features of highest mutual information with the class:
</source>
        <translation>die %1 Merkmale mit der höchsten Transinformation mit der Klasse:
</translation>
    </message>
    <message>
        <source>features of highest mutual information with the class:
</source>
        <translation>Merkmale mit der höchsten Transinformation mit der Klasse:
</translation>
    </message>
    <message>
        <source>Oversample smaller classes</source>
        <translation>Kleinere Klassen überabtasten</translation>
    </message>
    <message>
        <source>SMOTE (synthetic windows)</source>
        <translation>SMOTE (synthetische Fenster)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <source>Class balancing of the training windows (athlos train --balance).</source>
        <translation>Klassenausgleich der Trainingsfenster (athlos train --balance).</translation>
    </message>
    <message>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <source>Keep the K features of highest mutual information with the class, ranked inside each cross-validation fold (athlos train --select-features K).</source>
        <translation>Die K Merkmale mit der höchsten Transinformation mit der Klasse behalten, innerhalb jeder Kreuzvalidierungsfalte bestimmt (athlos train --select-features K).</translation>
    </message>
    <message>
        <source>Class balancing:</source>
        <translation>Klassenausgleich:</translation>
    </message>
    <message>
        <source>Features (mutual information):</source>
        <translation>Merkmale (Transinformation):</translation>
    </message>
    <message>
        <source>A stream name, or a pattern such as sim-imu-* (every matching stream of a recording is trained on: one per player of a team session).</source>
        <translation>Ein Stream-Name oder ein Muster wie sim-imu-* (jeder passende Stream einer Aufnahme wird trainiert: einer je Spieler einer Team-Session).</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Multi-athlete interaction features of detected events (athlos train --interaction k=K): the player&apos;s torso pitch and speed and the distance, speed and torso pitch of the K nearest opponents, from the other athletes&apos; IMU and positions streams of the recording (athlete and team attributes).</source>
        <translation>Multi-Athleten-Interaktionsmerkmale erkannter Ereignisse (athlos train --interaction k=K): Rumpfneigung und Geschwindigkeit des Spielers sowie Abstand, Geschwindigkeit und Rumpfneigung der K nächsten Gegner, aus den IMU- und Positions-Streams der anderen Athleten der Aufnahme (Attribute athlete und team).</translation>
    </message>
    <message>
        <source>Nearest opponents (interaction features):</source>
        <translation>Nächste Gegner (Interaktionsmerkmale):</translation>
    </message>
</context>
<context>
    <name>athlos::ui::TrajectoryPanel</name>
    <message>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Bahn</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <source>stream %1 has no x and y columns</source>
        <translation>Datenstrom %1 hat keine Spalten x und y</translation>
    </message>
    <message>
        <source>%1 — could not load: %2</source>
        <translation>%1 — konnte nicht geladen werden: %2</translation>
    </message>
    <message>
        <source>Select a position stream to show its path.</source>
        <translation>Wählen Sie einen Positionsdatenstrom aus, um seine Bahn zu zeigen.</translation>
    </message>
    <message>
        <source>%1 — loading…</source>
        <translation>%1 — wird geladen…</translation>
    </message>
    <message>
        <source>%1 — %2 samples</source>
        <translation>%1 — %2 Messwerte</translation>
    </message>
    <message>
        <source>Cursor</source>
        <translation>Cursor</translation>
    </message>
</context>
<context>
    <name>athlos::ui::UiEntry</name>
    <message>
        <source>unknown view &apos;%1&apos;; valid views: %2</source>
        <translation>unbekannte Ansicht &apos;%1&apos;; gültige Ansichten: %2</translation>
    </message>
    <message>
        <source>invalid screenshot size</source>
        <translation>ungültige Bildgröße</translation>
    </message>
    <message>
        <source>No position stream (lps-position, trajectory or gnss with x/y) in this project; showing the main view.</source>
        <translation>Kein Positionsdatenstrom (lps-position, trajectory oder gnss mit x/y) in diesem Projekt; die Hauptansicht wird gezeigt.</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>the project has no stream to annotate; import a recording first</source>
        <translation>das Projekt hat keinen Datenstrom zum Annotieren; importieren Sie zuerst eine Aufnahme</translation>
    </message>
    <message>
        <source>the project has no streams to show in view &apos;%1&apos;</source>
        <translation>das Projekt hat keine Datenströme für die Ansicht „%1“</translation>
    </message>
</context>
<context>
    <name>athlos::ui::VenueDrawing</name>
    <message>
        <source>Football pitch 105 × 68 m</source>
        <translation>Fußballfeld 105 × 68 m</translation>
    </message>
    <message>
        <source>Rugby pitch 100 × 70 m</source>
        <translation>Rugbyfeld 100 × 70 m</translation>
    </message>
    <message>
        <source>400 m track</source>
        <translation>400-m-Bahn</translation>
    </message>
    <message>
        <source>Rectangle (surveyed pitch)</source>
        <translation>Rechteck (vermessenes Feld)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Keine</translation>
    </message>
</context>
<context>
    <name>athlos::ui::VenuePlot</name>
    <message>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
    <message>
        <source>Walk</source>
        <translation>Lauf</translation>
    </message>
</context>
<context>
    <name>athlos::ui::VideoDock</name>
    <message>
        <source>Video</source>
        <translation>Video</translation>
    </message>
    <message>
        <source>◀ Frame</source>
        <translation>◀ Bild</translation>
    </message>
    <message>
        <source>One video frame back</source>
        <translation>Ein Videobild zurück</translation>
    </message>
    <message>
        <source>Frame ▶</source>
        <translation>Bild ▶</translation>
    </message>
    <message>
        <source>One video frame forward</source>
        <translation>Ein Videobild vor</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Offset of the video: t_recording = t_video + offset</source>
        <translation>Versatz des Videos: t_Aufnahme = t_Video + Versatz</translation>
    </message>
    <message>
        <source>Mark event in video</source>
        <translation>Ereignis im Video markieren</translation>
    </message>
    <message>
        <source>The event (clap, take-off…) is in the frame shown now</source>
        <translation>Das Ereignis (Klatschen, Absprung …) ist im jetzt gezeigten Bild</translation>
    </message>
    <message>
        <source>Mark event in signal</source>
        <translation>Ereignis im Signal markieren</translation>
    </message>
    <message>
        <source>The same event is at the cursor in the signal (e.g. the acceleration spike)</source>
        <translation>Dasselbe Ereignis liegt im Signal am Cursor (z. B. die Beschleunigungsspitze)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederholen</translation>
    </message>
    <message>
        <source>Recording:</source>
        <translation>Aufnahme:</translation>
    </message>
    <message>
        <source>Offset:</source>
        <translation>Versatz:</translation>
    </message>
    <message>
        <source>No project</source>
        <translation>Kein Projekt</translation>
    </message>
    <message>
        <source>No recording of this project has a video. Use View → Video… to attach one.</source>
        <translation>Keine Aufnahme dieses Projekts hat ein Video. Mit Ansicht → Video… lässt sich eines anhängen.</translation>
    </message>
    <message>
        <source>Recording &apos;%1&apos; has no video. Use View → Video… to attach one.</source>
        <translation>Aufnahme &apos;%1&apos; hat kein Video. Mit Ansicht → Video… lässt sich eines anhängen.</translation>
    </message>
    <message>
        <source>%1 (%2, %3 fps, %4 frames)</source>
        <translation>%1 (%2, %3 fps, %4 Bilder)</translation>
    </message>
    <message>
        <source>Video offset %1 s</source>
        <translation>Video-Versatz %1 s</translation>
    </message>
    <message>
        <source>Put the cursor where the video shows the event first.</source>
        <translation>Zuerst den Cursor dorthin setzen, wo das Video das Ereignis zeigt.</translation>
    </message>
    <message>
        <source>Synchronised: video %1 s = recording %2 s, offset %3 s.</source>
        <translation>Synchronisiert: Video %1 s = Aufnahme %2 s, Versatz %3 s.</translation>
    </message>
    <message>
        <source>Event marked in the video at %1 s (frame %2). Now put the cursor on the same event in a signal and press &quot;Mark event in signal&quot;.</source>
        <translation>Ereignis im Video bei %1 s (Bild %2) markiert. Jetzt den Cursor im Signal auf dasselbe Ereignis setzen und „Ereignis im Signal markieren“ drücken.</translation>
    </message>
    <message>
        <source>Event marked in the signal at %1 s. Now put the cursor where the video shows the same event and press &quot;Mark event in video&quot;.</source>
        <translation>Ereignis im Signal bei %1 s markiert. Jetzt den Cursor dorthin setzen, wo das Video dasselbe Ereignis zeigt, und „Ereignis im Video markieren“ drücken.</translation>
    </message>
    <message>
        <source>No video at %1 s: the video covers %2 … %3 s of the recording (offset %4 s).</source>
        <translation>Kein Video bei %1 s: Das Video deckt %2 … %3 s der Aufnahme ab (Versatz %4 s).</translation>
    </message>
    <message>
        <source>outside the video</source>
        <translation>außerhalb des Videos</translation>
    </message>
    <message>
        <source>frame %1 / %2 · video %3 s</source>
        <translation>Bild %1 / %2 · Video %3 s</translation>
    </message>
</context>
</TS>
