<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE" sourcelanguage="en">
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
</context>
<context>
    <name>athlos::ui::ParameterForm</name>
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
        <source>'%1' already exists; choose another name.</source>
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
        <source>'%1' is not an orientation stream (qw, qx, qy, qz)</source>
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
        <source>'%1' already exists; choose another name.</source>
        <translation>„%1“ existiert bereits; wählen Sie einen anderen Namen.</translation>
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
        <source>'%1' is not a stream of this project</source>
        <translation>„%1“ ist kein Datenstrom dieses Projekts</translation>
    </message>
    <message>
        <source>'%1' has no x/y samples</source>
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
    <name>athlos::ui::WizardParameterForm</name>
    <message>
        <source>(not set)</source>
        <translation>(nicht gesetzt)</translation>
    </message>
</context>
</TS>
