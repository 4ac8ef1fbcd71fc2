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
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>time (min)</source>
        <translation>Zeit (min)</translation>
    </message>
    <message>
        <source>speed (km/h)</source>
        <translation>Geschwindigkeit (km/h)</translation>
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
