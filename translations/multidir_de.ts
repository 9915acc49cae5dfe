<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AddPlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="50"/>
        <source>Add plane %1</source>
        <translation>Ebene %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>DeletePlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="55"/>
        <source>Delete plane %1</source>
        <translation>Ebene %1 löschen</translation>
    </message>
</context>
<context>
    <name>DeviceReading</name>
    <message>
        <location filename="../ui/device/device_reading.cpp" line="15"/>
        <source>unknown: not read yet</source>
        <translation>unbekannt: noch nicht gelesen</translation>
    </message>
    <message>
        <location filename="../ui/device/device_reading.cpp" line="18"/>
        <source>unknown since %1 (last read: %2)</source>
        <translation>unbekannt seit %1 (zuletzt gelesen: %2)</translation>
    </message>
</context>
<context>
    <name>GcodeExport</name>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="75"/>
        <source>Could not write %1: %2. Check that the folder can be written and the disk is not full.</source>
        <translation>%1 konnte nicht geschrieben werden: %2. Prüfen Sie, ob der Ordner beschreibbar und der Datenträger nicht voll ist.</translation>
    </message>
    <message>
        <source>Could not replace %1: it is in use or read-only.</source>
        <translation type="vanished">%1 konnte nicht ersetzt werden: die Datei wird verwendet oder ist schreibgeschützt.</translation>
    </message>
    <message>
        <source>Could not move %1 into place.</source>
        <translation type="vanished">%1 konnte nicht an den Zielort verschoben werden.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="35"/>
        <source>There is no sliced job to export: slice the plan first.</source>
        <translation>Es gibt kein Slicing-Ergebnis zum Exportieren: slicen Sie zuerst den Plan.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="40"/>
        <source>%1 is a file, not a folder: choose a folder for the G-code.</source>
        <translation>%1 ist eine Datei, kein Ordner: wählen Sie einen Ordner für den G-Code.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="45"/>
        <source>Could not create the folder %1: check that its parent exists and can be written.</source>
        <translation>Der Ordner %1 konnte nicht angelegt werden: prüfen Sie, ob der übergeordnete Ordner existiert und beschreibbar ist.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="51"/>
        <location filename="../ui/slicing/gcode_export.cpp" line="66"/>
        <location filename="../ui/slicing/gcode_export.cpp" line="83"/>
        <source>Could not export the G-code: %1</source>
        <translation>Der G-Code konnte nicht exportiert werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/gcode_export.cpp" line="57"/>
        <source>%1 holds files that are not a MultiDir job (%2 is one), so nothing was exported: choose an empty folder or one holding an earlier job.</source>
        <translation>%1 enthält Dateien, die nicht zu einem MultiDir-Auftrag gehören (%2 ist eine davon), daher wurde nichts exportiert: Wählen Sie einen leeren Ordner oder einen mit einem früheren Auftrag.</translation>
    </message>
</context>
<context>
    <name>MovePlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="39"/>
        <source>Move plane %1</source>
        <translation>Ebene %1 verschieben</translation>
    </message>
</context>
<context>
    <name>PlanEditRefusal</name>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="38"/>
        <source>The edit was not applied: %1 (%2)</source>
        <translation>Die Änderung wurde nicht übernommen: %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="43"/>
        <source>Plane %1 would cut the platform region: move it up or tilt it less.</source>
        <translation>Ebene %1 würde den Plattformbereich schneiden: verschieben Sie sie nach oben oder neigen Sie sie weniger.</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="45"/>
        <source>Plane %1 would leave a piece below it that no longer stands on the platform: move or tilt it so that the part below stays in one piece on the platform.</source>
        <translation>Ebene %1 würde darunter ein Stück zurücklassen, das nicht mehr auf der Plattform steht: verschieben oder neigen Sie sie so, dass der Teil darunter in einem Stück auf der Plattform bleibt.</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="50"/>
        <source>The machine cannot print along the normal of plane %1: tilt it back within the machine&apos;s limits.</source>
        <translation>Die Maschine kann nicht entlang der Normalen von Ebene %1 drucken: neigen Sie sie zurück in die Grenzen der Maschine.</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="54"/>
        <source>Plane %1 would cut nothing off: move it into the part it cuts.</source>
        <translation>Ebene %1 würde nichts abtrennen: verschieben Sie sie in das Teil, das sie schneidet.</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="56"/>
        <source>Plane %1 would leave nothing below it on the platform: move it up.</source>
        <translation>Unter Ebene %1 bliebe nichts auf der Plattform: verschieben Sie sie nach oben.</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="57"/>
        <source>Plane %1 was refused: %2</source>
        <translation>Ebene %1 wurde abgelehnt: %2</translation>
    </message>
    <message>
        <location filename="../ui/edit/refusal_text.cpp" line="66"/>
        <source>Plane %1 was not changed: with it there, plane %2 is refused. %3</source>
        <translation>Ebene %1 wurde nicht geändert: mit ihr dort wird Ebene %2 abgelehnt. %3</translation>
    </message>
</context>
<context>
    <name>ReplacePlanCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="59"/>
        <source>New search</source>
        <translation>Neue Suche</translation>
    </message>
</context>
<context>
    <name>TiltPlaneCommand</name>
    <message>
        <location filename="../ui/edit/plan_edit_commands.cpp" line="45"/>
        <source>Tilt plane %1</source>
        <translation>Ebene %1 neigen</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ApartJobRunner</name>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="16"/>
        <source>Slicing plate %1 of %2</source>
        <translation>Druckplatte %1 von %2 wird gesliced</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="19"/>
        <source>Slicing the model in one piece with supports, for comparison</source>
        <translation>Das Modell wird zum Vergleich in einem Stück mit Stützen gesliced</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="20"/>
        <source>Cutting the parts to fit the printer</source>
        <translation>Die Teile werden passend für den Drucker zerschnitten</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="21"/>
        <source>Placing the dowels</source>
        <translation>Die Dübel werden platziert</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="22"/>
        <source>Drilling the dowel holes</source>
        <translation>Die Dübellöcher werden gebohrt</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="23"/>
        <source>Sinking the part numbers</source>
        <translation>Die Teilenummern werden eingesenkt</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="24"/>
        <source>Laying the parts on plates</source>
        <translation>Die Teile werden auf Druckplatten gelegt</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="25"/>
        <source>Writing the parts and the 3MF</source>
        <translation>Die Teile und das 3MF werden geschrieben</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="26"/>
        <source>Drawing the assembly sheet</source>
        <translation>Das Montageblatt wird gezeichnet</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="33"/>
        <source>A part does not fit this printer even cut further: choose a printer with a larger bed, or scale the model down and search again.</source>
        <translation>Ein Teil passt auch weiter zerschnitten nicht in diesen Drucker: wählen Sie einen Drucker mit größerem Druckbett oder verkleinern Sie das Modell und suchen Sie erneut.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="37"/>
        <source>The slicer &apos;prusa-slicer&apos; was not found: install PrusaSlicer (scripts/install-deps.sh), or untick &quot;Slice the plates&quot;.</source>
        <translation>Der Slicer &apos;prusa-slicer&apos; wurde nicht gefunden: installieren Sie PrusaSlicer (scripts/install-deps.sh) oder entfernen Sie das Häkchen bei „Druckplatten slicen“.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="41"/>
        <source>The slicer failed on a plate: its command and last output lines are below. Try another printer, or untick &quot;Slice the plates&quot; to get the parts without G-code.</source>
        <translation>Der Slicer ist an einer Druckplatte gescheitert: sein Befehl und seine letzten Ausgabezeilen stehen unten. Versuchen Sie einen anderen Drucker oder entfernen Sie das Häkchen bei „Druckplatten slicen“, um die Teile ohne G-Code zu erhalten.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="45"/>
        <source>The parts could not be laid out or the dowels not placed: the reason is below. Choose a printer with a larger bed or other dowel options.</source>
        <translation>Die Teile konnten nicht angeordnet oder die Dübel nicht platziert werden: der Grund steht unten. Wählen Sie einen Drucker mit größerem Druckbett oder andere Dübeloptionen.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="49"/>
        <source>Drilling the dowel holes or sinking the numbers failed on a part (named below): try a smaller dowel diameter or another plan.</source>
        <translation>Das Bohren der Dübellöcher oder das Einsenken der Nummern ist an einem Teil (unten genannt) gescheitert: versuchen Sie einen kleineren Dübeldurchmesser oder einen anderen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="75"/>
        <source>The plan is being printed apart already.</source>
        <translation>Der Plan wird bereits getrennt gedruckt.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="79"/>
        <source>There is no plan to print apart: search the model first.</source>
        <translation>Es gibt keinen Plan zum getrennten Drucken: durchsuchen Sie zuerst das Modell.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="101"/>
        <source>Could not create a temporary folder for the parts: %1</source>
        <translation>Für die Teile konnte kein temporärer Ordner angelegt werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="97"/>
        <source>Not enough memory to print this plan apart.</source>
        <translation>Nicht genug Speicher, um diesen Plan getrennt zu drucken.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/apart_job_runner.cpp" line="98"/>
        <source>Unexpected error while printing the plan apart.</source>
        <translation>Unerwarteter Fehler beim getrennten Drucken des Plans.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ApartPanel</name>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="129"/>
        <source>The parts must fit this printer&apos;s bed and height; its settings slice the plates</source>
        <translation>Die Teile müssen auf das Druckbett und in die Höhe dieses Druckers passen; mit seinen Einstellungen werden die Druckplatten gesliced</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="130"/>
        <source>Printer</source>
        <translation>Drucker</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="131"/>
        <source>Slice the plates (PrusaSlicer) for the estimates</source>
        <translation>Druckplatten slicen (PrusaSlicer) für die Schätzungen</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="143"/>
        <source>Dowel diameter from</source>
        <translation>Dübeldurchmesser von</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="144"/>
        <source>Dowel diameter up to</source>
        <translation>Dübeldurchmesser bis</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="145"/>
        <source>Clearance in radius</source>
        <translation>Spiel im Radius</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="146"/>
        <source>Clearance in depth</source>
        <translation>Spiel in der Tiefe</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="147"/>
        <source>Wall around holes</source>
        <translation>Wandstärke um die Löcher</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="148"/>
        <source>Dowels per joint</source>
        <translation>Dübel je Verbindung</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="152"/>
        <source>Run</source>
        <translation>Starten</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="154"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="156"/>
        <source>Export...</source>
        <translation>Exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="158"/>
        <source>Write every part and dowel (STL), the 3MF, the G-code of every plate, the assembly sheet and apart.json to a folder</source>
        <translation>Jedes Teil und jeden Dübel (STL), das 3MF, den G-Code jeder Druckplatte, das Montageblatt und apart.json in einen Ordner schreiben</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Print</source>
        <translation>Druck</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Filament
(cm³)</source>
        <translation>Filament
(cm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="189"/>
        <source>Support
(cm³)</source>
        <translation>Stützen
(cm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="217"/>
        <source>Cancelled: nothing was written.</source>
        <translation>Abgebrochen: es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="241"/>
        <source>Assembly of %1</source>
        <translation>Montage von %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="249"/>
        <source>There is no plan to print apart: search the model first.</source>
        <translation>Es gibt keinen Plan zum getrennten Drucken: durchsuchen Sie zuerst das Modell.</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="254"/>
        <source>The printer &apos;%1&apos; could not be read: choose another one.</source>
        <translation>Der Drucker „%1“ konnte nicht gelesen werden: wählen Sie einen anderen.</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="258"/>
        <source>The dowel options do not fit together: %1</source>
        <translation>Die Dübeloptionen passen nicht zusammen: %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="276"/>
        <source>Nothing to export: run Print apart first.</source>
        <translation>Nichts zu exportieren: führen Sie zuerst „Getrennt drucken“ aus.</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="280"/>
        <source>The files could not be written: %1</source>
        <translation>Die Dateien konnten nicht geschrieben werden: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/apart_panel.cpp" line="283"/>
        <source>%n file(s) written to %1</source>
        <translation>
            <numerusform>%n Datei nach %1 geschrieben</numerusform>
            <numerusform>%n Dateien nach %1 geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="288"/>
        <source>Export the parts to a folder</source>
        <translation>Die Teile in einen Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="311"/>
        <source>%1 parts, %2 joints, %3 dowels, %4 plates; J_G apart %5 mm² (the plan: %6 mm²)</source>
        <translation>%1 Teile, %2 Verbindungen, %3 Dübel, %4 Druckplatten; J_G getrennt %5 mm² (der Plan: %6 mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="317"/>
        <source>Parts exploded</source>
        <translation>Teile in Explosionsansicht</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="318"/>
        <location filename="../ui/panels/apart_panel.cpp" line="351"/>
        <source>Plate %1</source>
        <translation>Druckplatte %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="352"/>
        <source>All plates</source>
        <translation>Alle Druckplatten</translation>
    </message>
    <message>
        <location filename="../ui/panels/apart_panel.cpp" line="353"/>
        <source>One piece with supports</source>
        <translation>Ein Stück mit Stützen</translation>
    </message>
</context>
<context>
    <name>multidir::ui::Autosave</name>
    <message>
        <location filename="../ui/project/autosave.cpp" line="83"/>
        <source>Cannot create the autosave folder %1.</source>
        <translation>Der Ordner für automatisches Speichern %1 kann nicht angelegt werden.</translation>
    </message>
    <message>
        <location filename="../ui/project/autosave.cpp" line="91"/>
        <source>Cannot lock a new autosave file in %1.</source>
        <translation>In %1 kann keine neue Datei für automatisches Speichern gesperrt werden.</translation>
    </message>
    <message>
        <location filename="../ui/project/autosave.cpp" line="95"/>
        <source>Autosave failed: %1 (%2)</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1 (%2)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::AxisPicker</name>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="17"/>
        <source>Open a model first: the rotation axis is picked on the platform under it.</source>
        <translation>Öffnen Sie zuerst ein Modell: die Drehachse wird auf der Plattform darunter gewählt.</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="26"/>
        <source>Click the first point on the platform (Esc cancels).</source>
        <translation>Klicken Sie auf den ersten Punkt auf der Plattform (Esc bricht ab).</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="35"/>
        <location filename="../ui/viewer/axis_picker.cpp" line="41"/>
        <source>Picking the rotation axis was cancelled.</source>
        <translation>Die Wahl der Drehachse wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="49"/>
        <source>Click the second point on the platform: the axis runs from the first point to it.</source>
        <translation>Klicken Sie auf den zweiten Punkt auf der Plattform: die Achse verläuft vom ersten Punkt zu diesem.</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="54"/>
        <source>The second point is less than %1 mm from the first: click farther away.</source>
        <translation>Der zweite Punkt liegt weniger als %1 mm vom ersten entfernt: klicken Sie weiter entfernt.</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="61"/>
        <source>Rotation axis picked: (%1, %2, %3).</source>
        <translation>Drehachse gewählt: (%1, %2, %3).</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="71"/>
        <source>The view looks along the platform: turn the view and click again.</source>
        <translation>Die Ansicht blickt parallel zur Plattform: drehen Sie die Ansicht und klicken Sie erneut.</translation>
    </message>
    <message>
        <location filename="../ui/viewer/axis_picker.cpp" line="79"/>
        <source>That click missed the platform: click on the grey disc under the model.</source>
        <translation>Der Klick hat die Plattform verfehlt: klicken Sie auf die graue Scheibe unter dem Modell.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::CellPanel</name>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="54"/>
        <source>Robot cell: the arm carries the platform under a fixed extruder</source>
        <translation>Roboterzelle: der Arm trägt die Plattform unter einem feststehenden Extruder</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="58"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="59"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="69"/>
        <source>The nozzle tip in the robot base frame (measure it with the TCP; docs/robot-cell.md)</source>
        <translation>Die Düsenspitze im Basiskoordinatensystem des Roboters (mit dem TCP messen; docs/robot-cell.md)</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="70"/>
        <source>Unit vector from the tip up into the extruder, robot base frame</source>
        <translation>Einheitsvektor von der Spitze nach oben in den Extruder, im Basiskoordinatensystem des Roboters</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="71"/>
        <source>Flange to platform centre (the TCP): translation; the calibration</source>
        <translation>Flansch zur Plattformmitte (der TCP): Verschiebung; die Kalibrierung</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="72"/>
        <source>Flange to platform centre: rotation vector (axis times angle), degrees</source>
        <translation>Flansch zur Plattformmitte: Drehvektor (Achse mal Winkel), Grad</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="74"/>
        <source>Load cell...</source>
        <translation>Zelle laden...</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="76"/>
        <source>Save cell...</source>
        <translation>Zelle speichern...</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="86"/>
        <source>Find extruder position</source>
        <translation>Extruderposition finden</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="88"/>
        <source>Scores nozzle positions over the arm&apos;s workspace by the share of the plan&apos;s platform poses reachable with margin (multidir cell reach)</source>
        <translation>Bewertet Düsenpositionen im Arbeitsraum des Arms nach dem Anteil der Plattformposen des Plans, die mit Reserve erreichbar sind (multidir cell reach)</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="90"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="100"/>
        <source>Use this position</source>
        <translation>Diese Position verwenden</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="106"/>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="107"/>
        <source>Nozzle tip:</source>
        <translation>Düsenspitze:</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="108"/>
        <source>Nozzle axis:</source>
        <translation>Düsenachse:</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="109"/>
        <source>Flange to platform:</source>
        <translation>Flansch zur Plattform:</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="110"/>
        <source>Platform rotation:</source>
        <translation>Plattformdrehung:</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="111"/>
        <source>Table height:</source>
        <translation>Tischhöhe:</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="137"/>
        <source>Load robot cell</source>
        <translation>Roboterzelle laden</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="137"/>
        <location filename="../ui/panels/cell_panel.cpp" line="141"/>
        <source>Robot cell (*.json)</source>
        <translation>Roboterzelle (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="141"/>
        <source>Save robot cell</source>
        <translation>Roboterzelle speichern</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="155"/>
        <source>Finding the extruder position was cancelled.</source>
        <translation>Die Suche nach der Extruderposition wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="189"/>
        <source>Could not load the cell file %1: %2</source>
        <translation>Die Zellendatei %1 konnte nicht geladen werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="195"/>
        <source>Cell loaded from %1.</source>
        <translation>Zelle aus %1 geladen.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="201"/>
        <source>There is no cell to save.</source>
        <translation>Es gibt keine Zelle zum Speichern.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="206"/>
        <source>Could not save the cell: %1</source>
        <translation>Die Zelle konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="209"/>
        <source>Cell saved as %1.</source>
        <translation>Zelle als %1 gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="223"/>
        <source>No cell.</source>
        <translation>Keine Zelle.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="241"/>
        <source>Cell check: sound (%1, nozzle tip at %2, %3, %4 mm).</source>
        <translation>Zellenprüfung: in Ordnung (%1, Düsenspitze bei %2, %3, %4 mm).</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/cell_panel.cpp" line="248"/>
        <source>Cell check: %n problem(s)</source>
        <translation>
            <numerusform>Zellenprüfung: %n Problem</numerusform>
            <numerusform>Zellenprüfung: %n Probleme</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="293"/>
        <source>There is no cell: choose the robot cell machine or load a cell file.</source>
        <translation>Es gibt keine Zelle: wählen Sie die Maschine Roboterzelle oder laden Sie eine Zellendatei.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="298"/>
        <source>There is no plan: the reach map scores the plan&apos;s platform poses. Run a search or open a plan.</source>
        <translation>Es gibt keinen Plan: die Erreichbarkeitskarte bewertet die Plattformposen des Plans. Starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="303"/>
        <source>The plan&apos;s poses cannot be found: %1</source>
        <translation>Die Posen des Plans können nicht bestimmt werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="328"/>
        <source>The reach map failed: %1</source>
        <translation>Die Erreichbarkeitskarte ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="346"/>
        <source>Best nozzle position: %1, %2, %3 mm, %4 % of the plan&apos;s poses reachable with margin (least reach margin %5 mm) over %6 positions.</source>
        <translation>Beste Düsenposition: %1, %2, %3 mm, %4 % der Posen des Plans mit Reserve erreichbar (kleinste Reichweitenreserve %5 mm), über %6 Positionen.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="364"/>
        <source>Finding the extruder position...</source>
        <translation>Extruderposition wird gesucht...</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="387"/>
        <source>The nozzle tip is now at the reach map&apos;s best position; move the extruder there and measure it again.</source>
        <translation>Die Düsenspitze steht jetzt an der besten Position der Erreichbarkeitskarte; bringen Sie den Extruder dorthin und messen Sie sie erneut.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="160"/>
        <source>The cell changed since the reach map was made (the map scores the arm, the nozzle axis, the platform, the table and the margins it had): find the extruder position again.</source>
        <translation>Die Zelle hat sich geändert, seit die Erreichbarkeitskarte erstellt wurde (die Karte bewertet den Arm, die Düsenachse, die Plattform, den Tisch und die Abstände, die sie damals hatte): bestimmen Sie die Extruderposition erneut.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="165"/>
        <source>The plan changed since the reach map was made (the map scores the plan&apos;s poses): find the extruder position again.</source>
        <translation>Der Plan hat sich geändert, seit die Erreichbarkeitskarte erstellt wurde (die Karte bewertet die Posen des Plans): bestimmen Sie die Extruderposition erneut.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="175"/>
        <source>Supports were grown for the plan since the reach map was made (the map scores their poses too): find the extruder position again.</source>
        <translation>Seit die Erreichbarkeitskarte erstellt wurde, wurden Stützen für den Plan erzeugt (die Karte bewertet auch ihre Posen): bestimmen Sie die Extruderposition erneut.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_panel.cpp" line="337"/>
        <source>The plan or the cell changed while the reach map was made: find the extruder position again.</source>
        <translation>Der Plan oder die Zelle hat sich geändert, während die Erreichbarkeitskarte erstellt wurde: bestimmen Sie die Extruderposition erneut.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::CellViewPanel</name>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="31"/>
        <source>Show on the cell</source>
        <translation>In der Zelle zeigen</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="33"/>
        <source>The sliced job on the robot cell: the arm, the platform and the part at the poses the robot programs command (multidir robot-program)</source>
        <translation>Das Slicing-Ergebnis in der Roboterzelle: der Arm, die Plattform und das Teil in den Posen, die die Roboterprogramme vorgeben (multidir robot-program)</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="35"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="38"/>
        <source>Back to the plan</source>
        <translation>Zurück zum Plan</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="47"/>
        <location filename="../ui/panels/cell_view_panel.cpp" line="96"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="96"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="114"/>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="123"/>
        <source>The cell changed: show the job on it again.</source>
        <translation>Die Zelle hat sich geändert: zeigen Sie den Auftrag erneut in ihr.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="134"/>
        <source>There is no robot cell: choose the machine &quot;robot arm under a fixed extruder&quot;.</source>
        <translation>Es gibt keine Roboterzelle: wählen Sie die Maschine „Roboterarm unter einem feststehenden Extruder“.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="138"/>
        <source>The plan is not sliced: slice it with the cell&apos;s profile (ur5-cell-0.8) first.</source>
        <translation>Für den Plan gibt es kein Slicing-Ergebnis: slicen Sie ihn zuerst mit dem Profil der Zelle (ur5-cell-0.8).</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="162"/>
        <source>The job cannot be posed on the cell: %1</source>
        <translation>Der Auftrag kann nicht in die Zelle gestellt werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="174"/>
        <source>Converting the job for the cell...</source>
        <translation>Der Auftrag wird für die Zelle umgewandelt...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/cell_view_panel.cpp" line="244"/>
        <source>%n step(s) on the %1, %2 moves.</source>
        <translation>
            <numerusform>%n Schritt am %1, %2 Bewegungen.</numerusform>
            <numerusform>%n Schritte am %1, %2 Bewegungen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="268"/>
        <source>Step %1 of %2: no move converted (the arm at home).</source>
        <translation>Schritt %1 von %2: keine Bewegung umgewandelt (der Arm in Grundstellung).</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="272"/>
        <source>Step %1 of %2, move %3 of %4 (%5, line %6)</source>
        <translation>Schritt %1 von %2, Bewegung %3 von %4 (%5, Zeile %6)</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="61"/>
        <source>Show the reach map</source>
        <translation>Erreichbarkeitskarte zeigen</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="63"/>
        <source>The nozzle positions &quot;Find extruder position&quot; scored (Machine tab), coloured from red (none of the plan&apos;s poses reachable with margin) to blue (all of them); the best one ringed in white</source>
        <translation>Die Düsenpositionen, die „Extruderposition finden“ bewertet hat (Registerkarte „Maschine“), gefärbt von Rot (keine Pose des Plans mit Abstand erreichbar) bis Blau (alle); die beste weiß umrandet</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="196"/>
        <source>Reach map: %1 nozzle positions every %2 mm; the best, ringed, at %3, %4, %5 mm with %6 % of the plan&apos;s poses reachable with margin.</source>
        <translation>Erreichbarkeitskarte: %1 Düsenpositionen im Abstand von %2 mm; die beste (umrandet) bei %3, %4, %5 mm, mit %6 % der Posen des Plans mit Abstand erreichbar.</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="205"/>
        <source>Reach map not shown: %1</source>
        <translation>Erreichbarkeitskarte nicht gezeigt: %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/cell_view_panel.cpp" line="229"/>
        <source>Plan&apos;s poses reachable with margin (%)</source>
        <translation>Mit Abstand erreichbare Posen des Plans (%)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ConnectionForm</name>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="37"/>
        <source>Rotary platform (4-DOF)</source>
        <translation>Drehplattform (4-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="38"/>
        <source>Robot arm (5-DOF)</source>
        <translation>Roboterarm (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="40"/>
        <source>Robot cell (5-DOF, fixed extruder)</source>
        <translation>Roboterzelle (5-DOF, fester Extruder)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="42"/>
        <source>Robot cell (5-DOF, Universal Robots: the arm carries the part under a fixed extruder)</source>
        <translation>Roboterzelle (5-DOF, Universal Robots: der Arm führt das Teil unter einem festen Extruder)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="47"/>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="48"/>
        <source>Modbus RTU (serial)</source>
        <translation>Modbus RTU (seriell)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="57"/>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="58"/>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="59"/>
        <source>Unit id:</source>
        <translation>Unit-ID:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="74"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="75"/>
        <source>Even</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="76"/>
        <source>Odd</source>
        <translation>Ungerade</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="80"/>
        <source>Serial port:</source>
        <translation>Serielle Schnittstelle:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="81"/>
        <source>Baud:</source>
        <translation>Baudrate:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="82"/>
        <source>Parity:</source>
        <translation>Parität:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="83"/>
        <source>Data bits:</source>
        <translation>Datenbits:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="84"/>
        <source>Stop bits:</source>
        <translation>Stoppbits:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="85"/>
        <source>Slave id:</source>
        <translation>Slave-ID:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="92"/>
        <location filename="../ui/device/connection_form.cpp" line="95"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="93"/>
        <source>How long to wait for the first byte of a reply, and for a TCP connection.</source>
        <translation>Wie lange auf das erste Byte einer Antwort und auf eine TCP-Verbindung gewartet wird.</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="96"/>
        <source>How long to wait between two bytes of one reply.</source>
        <translation>Wie lange zwischen zwei Bytes einer Antwort gewartet wird.</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="105"/>
        <source> °/s</source>
        <translation> °/s</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="106"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="107"/>
        <source>Of the robot program&apos;s maximal rotation speed.</source>
        <translation>Anteil an der größten Drehgeschwindigkeit des Roboterprogramms.</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="108"/>
        <location filename="../ui/device/connection_form.cpp" line="109"/>
        <source>Speed:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="114"/>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="115"/>
        <source>Transport:</source>
        <translation>Übertragung:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="119"/>
        <source>Response timeout:</source>
        <translation>Antwort-Timeout:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="120"/>
        <source>Byte timeout:</source>
        <translation>Byte-Timeout:</translation>
    </message>
</context>
<context>
    <name>multidir::ui::DeviceLink</name>
    <message>
        <location filename="../ui/device/device_link.cpp" line="30"/>
        <source>stall: the platform made no progress, so MultiDir stopped it</source>
        <translation>blockiert: die Plattform kam nicht voran, daher hat MultiDir sie angehalten</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="31"/>
        <source>stall: the controller lost its position (following error)</source>
        <translation>blockiert: die Steuerung hat ihre Position verloren (Schleppfehler)</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="34"/>
        <source>heartbeat lost: the controller stopped because MultiDir went silent</source>
        <translation>Heartbeat verloren: die Steuerung hat angehalten, weil MultiDir nicht mehr antwortete</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="37"/>
        <source>a limit switch was hit</source>
        <translation>ein Endschalter wurde ausgelöst</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="40"/>
        <source>the controller rejected a command (not homed, or beyond its own limits)</source>
        <translation>die Steuerung hat einen Befehl abgelehnt (nicht referenziert oder außerhalb ihrer eigenen Grenzen)</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="43"/>
        <source>emergency stop: the power stage is off</source>
        <translation>Not-Halt: die Endstufe ist ausgeschaltet</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="46"/>
        <source>unknown fault code %1</source>
        <translation>unbekannter Fehlercode %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="49"/>
        <source>; press Clear fault, then Enable and Home</source>
        <translation>; drücken Sie „Fehler löschen“, dann „Aktivieren“ und „Referenzfahrt“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="55"/>
        <source>the robot program is not running: start it on the teach pendant</source>
        <translation>das Roboterprogramm läuft nicht: starten Sie es am Handbediengerät</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="57"/>
        <source>halted by an emergency stop: press Clear fault before moving again</source>
        <translation>durch einen Not-Halt angehalten: drücken Sie „Fehler löschen“, bevor Sie wieder verfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="61"/>
        <source>the target was beyond the robot program&apos;s limits; press Clear fault</source>
        <translation>das Ziel lag außerhalb der Grenzen des Roboterprogramms; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="63"/>
        <source>the robot stopped because MultiDir&apos;s heartbeat was lost; press Clear fault</source>
        <translation>der Roboter hat angehalten, weil der Heartbeat von MultiDir ausblieb; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="65"/>
        <source>the robot program got an unknown command; press Clear fault</source>
        <translation>das Roboterprogramm hat einen unbekannten Befehl erhalten; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="67"/>
        <source>robot program fault code %1; press Clear fault</source>
        <translation>Fehlercode %1 des Roboterprogramms; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="213"/>
        <source>Cannot connect with these settings: %1</source>
        <translation>Mit diesen Einstellungen ist keine Verbindung möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="216"/>
        <source>Could not connect yet; MultiDir keeps trying. %1</source>
        <translation>Noch keine Verbindung; MultiDir versucht es weiter. %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="244"/>
        <source>Enable</source>
        <translation>Aktivieren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="247"/>
        <source>%1 does not apply to the robot arm: its program enables the arm; start it on the teach pendant.</source>
        <translation>%1 gilt nicht für den Roboterarm: sein Programm aktiviert den Arm; starten Sie es am Handbediengerät.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="257"/>
        <source>Home</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="264"/>
        <source>Go to %1</source>
        <translation>%1 anfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="267"/>
        <source>%1 refused: the robot arm takes a tilt and an azimuth.</source>
        <translation>%1 abgelehnt: der Roboterarm erwartet eine Neigung und einen Azimut.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="274"/>
        <source>Go to tilt %1, azimuth %2</source>
        <translation>Neigung %1, Azimut %2 anfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="277"/>
        <source>%1 refused: the rotary platform takes one angle.</source>
        <translation>%1 abgelehnt: die Drehplattform erwartet einen einzigen Winkel.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="284"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="290"/>
        <location filename="../ui/device/hardware_panel.cpp" line="621"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="296"/>
        <source>Clear fault</source>
        <translation>Fehler löschen</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="314"/>
        <source>%1 refused: not connected; connect to the device first.</source>
        <translation>%1 abgelehnt: nicht verbunden; verbinden Sie zuerst das Gerät.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="326"/>
        <source>%1 refused, nothing was sent: %2</source>
        <translation>%1 abgelehnt, nichts wurde gesendet: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="328"/>
        <source>%1 cancelled by Stop, E-STOP or Disconnect: %2</source>
        <translation>%1 durch Stopp, NOT-HALT oder Trennen abgebrochen: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="330"/>
        <source>%1 failed at the device or on the link: %2</source>
        <translation>%1 ist am Gerät oder auf der Verbindung fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ErrorText</name>
    <message>
        <location filename="../ui/common/error_text.cpp" line="18"/>
        <source>The file does not exist or cannot be read.</source>
        <translation>Die Datei existiert nicht oder kann nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="20"/>
        <source>This file type is not supported: use STL, OBJ, OFF or PLY.</source>
        <translation>Dieser Dateityp wird nicht unterstützt: verwenden Sie STL, OBJ, OFF oder PLY.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="22"/>
        <source>The file is damaged or does not follow its format.</source>
        <translation>Die Datei ist beschädigt oder entspricht nicht ihrem Format.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="24"/>
        <source>The model is larger than MultiDir accepts.</source>
        <translation>Das Modell ist größer, als MultiDir annimmt.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="26"/>
        <source>The file could not be written.</source>
        <translation>Die Datei konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="28"/>
        <source>The file contains no triangles.</source>
        <translation>Die Datei enthält keine Dreiecke.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="30"/>
        <source>Some vertex coordinates are not numbers.</source>
        <translation>Einige Eckpunktkoordinaten sind keine Zahlen.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="32"/>
        <source>The surface is not a clean solid: some edges or vertices are shared by too many faces.</source>
        <translation>Die Oberfläche ist kein sauberer Körper: einige Kanten oder Eckpunkte gehören zu zu vielen Flächen.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="35"/>
        <source>The surface has holes, so it does not enclose a solid. Close them in a mesh repair tool.</source>
        <translation>Die Oberfläche hat Löcher und umschließt daher keinen Körper. Schließen Sie sie mit einem Netzreparaturwerkzeug.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="38"/>
        <source>The faces of the surface point in inconsistent directions.</source>
        <translation>Die Flächen der Oberfläche zeigen in widersprüchliche Richtungen.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="40"/>
        <source>A setting is out of its allowed range.</source>
        <translation>Eine Einstellung liegt außerhalb ihres zulässigen Bereichs.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="42"/>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="44"/>
        <source>The device does not answer: check its power, cable or network.</source>
        <translation>Das Gerät antwortet nicht: prüfen Sie Stromversorgung, Kabel oder Netzwerk.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="46"/>
        <source>The device reported an error.</source>
        <translation>Das Gerät hat einen Fehler gemeldet.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="48"/>
        <source>A program MultiDir runs (the slicer) is missing or failed.</source>
        <translation>Ein von MultiDir ausgeführtes Programm (der Slicer) fehlt oder ist fehlgeschlagen.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="50"/>
        <source>The produced G-code failed MultiDir&apos;s safety checks.</source>
        <translation>Der erzeugte G-Code hat die Sicherheitsprüfungen von MultiDir nicht bestanden.</translation>
    </message>
    <message>
        <location filename="../ui/common/error_text.cpp" line="54"/>
        <source>An internal error occurred: please report it with the model.</source>
        <translation>Ein interner Fehler ist aufgetreten: bitte melden Sie ihn zusammen mit dem Modell.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::HardwarePanel</name>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="71"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="73"/>
        <source>Reconnecting…</source>
        <translation>Verbindung wird wiederhergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="74"/>
        <source>Connecting…</source>
        <translation>Verbindung wird hergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="76"/>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="78"/>
        <source>Fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="86"/>
        <source>idle</source>
        <translation>im Leerlauf</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="88"/>
        <source>turning the platform</source>
        <translation>Plattform wird gedreht</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="90"/>
        <source>settling</source>
        <translation>Beruhigungszeit</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="92"/>
        <source>printing</source>
        <translation>Druck läuft</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="94"/>
        <source>paused</source>
        <translation>pausiert</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="96"/>
        <source>finished</source>
        <translation>abgeschlossen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="98"/>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="100"/>
        <source>stopped by a device problem</source>
        <translation>durch ein Geräteproblem angehalten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="107"/>
        <source>angle %1</source>
        <translation>Winkel %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="108"/>
        <location filename="../ui/device/hardware_panel.cpp" line="599"/>
        <source>tilt %1, azimuth %2</source>
        <translation>Neigung %1, Azimut %2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="117"/>
        <source>Clear fault, then Enable and Home</source>
        <translation>„Fehler löschen“, dann „Aktivieren“ und „Referenzfahrt“</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="118"/>
        <source>Clear fault; the robot program then takes moves again</source>
        <translation>„Fehler löschen“; danach nimmt das Roboterprogramm wieder Fahrbefehle an</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="234"/>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="237"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="238"/>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="239"/>
        <source>Closes the link without commanding the device; its heartbeat watchdog stops it.</source>
        <translation>Schließt die Verbindung, ohne dem Gerät einen Befehl zu senden; sein Heartbeat-Watchdog hält es an.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="253"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="264"/>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="266"/>
        <source>Enabled:</source>
        <translation>Aktiviert:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="267"/>
        <source>Position:</source>
        <translation>Position:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="268"/>
        <source>Moving:</source>
        <translation>In Bewegung:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="269"/>
        <source>Homed:</source>
        <translation>Referenziert:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="270"/>
        <source>Fault:</source>
        <translation>Fehler:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="271"/>
        <source>Heartbeat:</source>
        <translation>Heartbeat:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="272"/>
        <source>Last problem:</source>
        <translation>Letztes Problem:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="277"/>
        <source>Controls</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="278"/>
        <source>Enable</source>
        <translation>Aktivieren</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="278"/>
        <source>Switches the platform&apos;s drive on.</source>
        <translation>Schaltet den Antrieb der Plattform ein.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="279"/>
        <source>Home</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="280"/>
        <source>Rotary platform: finds the home switch (0°). Robot arm: levels the platform (tilt 0°).</source>
        <translation>Drehplattform: sucht den Referenzschalter (0°). Roboterarm: richtet die Plattform waagerecht aus (Neigung 0°).</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="281"/>
        <source>Clear fault</source>
        <translation>Fehler löschen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="282"/>
        <source>Resets the device after a fault or an E-STOP; then enable and home again.</source>
        <translation>Setzt das Gerät nach einem Fehler oder NOT-HALT zurück; danach erneut aktivieren und referenzieren.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="286"/>
        <source>Tilt</source>
        <translation>Neigung</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="287"/>
        <source>Azimuth</source>
        <translation>Azimut</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="288"/>
        <source>Jog −</source>
        <translation>Tippen −</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="289"/>
        <source>Jog +</source>
        <translation>Tippen +</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="293"/>
        <source>Angle:</source>
        <translation>Winkel:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="294"/>
        <source>Tilt:</source>
        <translation>Neigung:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="295"/>
        <source>Azimuth:</source>
        <translation>Azimut:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="296"/>
        <source>Go to</source>
        <translation>Anfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="326"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="326"/>
        <source>Decelerates and stops; cancels queued commands.</source>
        <translation>Bremst ab und hält an; verwirft wartende Befehle.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="327"/>
        <location filename="../ui/device/hardware_panel.cpp" line="348"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="376"/>
        <source>Press when the region asked for has been printed (by hand: a region the connected printer prints goes on by itself).</source>
        <translation>Drücken, sobald der angeforderte Bereich gedruckt ist (nur beim Drucken von Hand: bei einem Bereich, den der verbundene Drucker druckt, geht es von selbst weiter).</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="495"/>
        <source>the platform</source>
        <translation>die Plattform</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="496"/>
        <source>the printer</source>
        <translation>den Drucker</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="499"/>
        <source>E-STOP sent to %1. To go on: %2%3.</source>
        <translation>NOT-HALT an %1 gesendet. Zum Fortfahren: %2%3.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="500"/>
        <source> and </source>
        <translation> und </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="501"/>
        <source>; for the printer, Clear printer E-STOP and restart its firmware</source>
        <translation>; beim Drucker „Drucker-NOT-HALT aufheben“ und seine Firmware neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="516"/>
        <source>Platform: stop confirmed by the device.</source>
        <translation>Plattform: Halt vom Gerät bestätigt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="517"/>
        <source>Platform: stop not confirmed yet; MultiDir keeps resending it.</source>
        <translation>Plattform: Halt noch nicht bestätigt; MultiDir sendet ihn weiter erneut.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="522"/>
        <source>Printer: emergency stop confirmed by the printer.</source>
        <translation>Drucker: Not-Halt vom Drucker bestätigt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="523"/>
        <source>Printer: emergency stop not confirmed yet (%1); MultiDir keeps resending it.</source>
        <translation>Drucker: Not-Halt noch nicht bestätigt (%1); MultiDir sendet ihn weiter erneut.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="639"/>
        <source>The print run stopped: %1. Fix the device (%2), then press Resume to retry this step, or Abort.</source>
        <translation>Der Drucklauf wurde angehalten: %1. Bringen Sie das Gerät in Ordnung (%2) und drücken Sie dann „Fortsetzen“, um diesen Schritt zu wiederholen, oder „Abbrechen“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="301"/>
        <source>Jog step:</source>
        <translation>Tippschritt:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="358"/>
        <source>Print run</source>
        <translation>Drucklauf</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="360"/>
        <location filename="../ui/device/hardware_panel.cpp" line="851"/>
        <source>Start run</source>
        <translation>Lauf starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="361"/>
        <source>Turns the platform to each region&apos;s orientation in printing order and asks for each region to be printed.</source>
        <translation>Dreht die Plattform in Druckreihenfolge in die Ausrichtung jedes Bereichs und fordert dazu auf, jeden Bereich zu drucken.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="375"/>
        <location filename="../ui/device/hardware_panel.cpp" line="419"/>
        <source>Region done</source>
        <translation>Bereich fertig</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="378"/>
        <location filename="../ui/device/hardware_panel.cpp" line="420"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="379"/>
        <location filename="../ui/device/hardware_panel.cpp" line="421"/>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="380"/>
        <source>Continues a paused run, or retries the current step after a device problem.</source>
        <translation>Setzt einen pausierten Lauf fort oder wiederholt nach einem Geräteproblem den aktuellen Schritt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="381"/>
        <location filename="../ui/device/hardware_panel.cpp" line="422"/>
        <location filename="../ui/device/hardware_panel.cpp" line="699"/>
        <source>Abort</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="404"/>
        <source>Step:</source>
        <translation>Schritt:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="405"/>
        <source>Elapsed:</source>
        <translation>Verstrichen:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="441"/>
        <source>The link to %1 was lost at %2. The values below are not the device&apos;s any more; MultiDir keeps trying to reconnect.</source>
        <translation>Die Verbindung zu %1 ist um %2 abgerissen. Die Werte unten stammen nicht mehr vom Gerät; MultiDir versucht weiter, die Verbindung wiederherzustellen.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="445"/>
        <source>The print run is paused: a region being printed may finish, no new region starts. Press Resume once the link is back.</source>
        <translation>Der Drucklauf ist pausiert: ein Bereich, der gerade gedruckt wird, darf fertig werden, aber kein neuer Bereich beginnt. Drücken Sie „Fortsetzen“, sobald die Verbindung wieder steht.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="448"/>
        <source>%1 does not answer: %2</source>
        <translation>%1 antwortet nicht: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="451"/>
        <source>The link is back. The print run is still paused since the link was lost: check the platform, then press Resume.</source>
        <translation>Die Verbindung steht wieder. Der Drucklauf ist seit dem Verbindungsabbruch weiterhin pausiert: prüfen Sie die Plattform und drücken Sie dann „Fortsetzen“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="558"/>
        <source>Cannot connect with these settings: %1</source>
        <translation>Mit diesen Einstellungen ist keine Verbindung möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="563"/>
        <source>Connecting to %1…</source>
        <translation>Verbindung mit %1 wird hergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="572"/>
        <source>Disconnected.</source>
        <translation>Getrennt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="582"/>
        <source>Not reachable; MultiDir keeps trying…</source>
        <translation>Nicht erreichbar; MultiDir versucht es weiter…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="584"/>
        <source>Link lost at %1; reconnecting…</source>
        <translation>Verbindung um %1 abgerissen; Verbindung wird wiederhergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="594"/>
        <source>no: press Enable</source>
        <translation>nein: drücken Sie „Aktivieren“</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="595"/>
        <source>%1 (target %2)</source>
        <translation>%1 (Ziel %2)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="596"/>
        <source>homing</source>
        <translation>Referenzfahrt läuft</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="594"/>
        <location filename="../ui/device/hardware_panel.cpp" line="596"/>
        <location filename="../ui/device/hardware_panel.cpp" line="597"/>
        <location filename="../ui/device/hardware_panel.cpp" line="600"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="596"/>
        <location filename="../ui/device/hardware_panel.cpp" line="597"/>
        <location filename="../ui/device/hardware_panel.cpp" line="600"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="601"/>
        <source>not needed (robot arm)</source>
        <translation>nicht nötig (Roboterarm)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="603"/>
        <location filename="../ui/device/hardware_panel.cpp" line="608"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="622"/>
        <source>%1: sent to the device. To go on: %2.</source>
        <translation>%1: an das Gerät gesendet. Zum Weitermachen: %2.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="624"/>
        <source>%1: sent to the device.</source>
        <translation>%1: an das Gerät gesendet.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="630"/>
        <source>Connected to %1.</source>
        <translation>Verbunden mit %1.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="643"/>
        <source>The print run is finished: every region was printed.</source>
        <translation>Der Drucklauf ist abgeschlossen: jeder Bereich wurde gedruckt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="645"/>
        <source>The print run was aborted.</source>
        <translation>Der Drucklauf wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="662"/>
        <source>Region %1 is printed by %2 (%3); the run goes on when the printer reports it complete.</source>
        <translation>Bereich %1 wird von %2 gedruckt (%3); der Lauf geht weiter, sobald der Drucker ihn als fertig meldet.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="667"/>
        <source>Print region %1 (file %2), then press Region done.</source>
        <translation>Drucken Sie Bereich %1 (Datei %2) und drücken Sie dann „Bereich fertig“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="813"/>
        <source>Start run refused: not connected; connect to the device first.</source>
        <translation>„Lauf starten“ abgelehnt: nicht verbunden; verbinden Sie zuerst das Gerät.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="821"/>
        <location filename="../ui/device/hardware_panel.cpp" line="828"/>
        <location filename="../ui/device/hardware_panel.cpp" line="850"/>
        <source>Start run refused: %1</source>
        <translation>„Lauf starten“ abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="854"/>
        <source>The plan is not sliced: each region is printed by hand (Region done). Slice the plan to have the printer print them.</source>
        <translation>Für den Plan gibt es kein Slicing-Ergebnis: jeder Bereich wird von Hand gedruckt („Bereich fertig“). Slicen Sie den Plan, damit der Drucker die Bereiche druckt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="856"/>
        <source>The sliced job has %1 steps, the plan %2 regions: each region is printed by hand (Region done). Slice the plan again.</source>
        <translation>Das Slicing-Ergebnis hat %1 Schritte, der Plan %2 Bereiche: jeder Bereich wird von Hand gedruckt („Bereich fertig“). Slicen Sie den Plan erneut.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="864"/>
        <source>%1 refused: %2</source>
        <translation>%1 abgelehnt: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="884"/>
        <source>Limits: %1 to %2 in steps of %3</source>
        <translation>Grenzen: %1 bis %2 in Schritten von %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="886"/>
        <source>Limits: tilt up to %1, %n forbidden cone(s)</source>
        <translation>
            <numerusform>Grenzen: Neigung bis %1, %n verbotener Kegel</numerusform>
            <numerusform>Grenzen: Neigung bis %1, %n verbotene Kegel</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="889"/>
        <source> (machine profile)</source>
        <translation> (Maschinenprofil)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="891"/>
        <source> (defaults: the machine profile is for a %1 machine)</source>
        <translation> (Standardwerte: das Maschinenprofil gilt für eine %1-Maschine)</translation>
    </message>
    <message>
        <source> (defaults: no machine profile)</source>
        <translation type="vanished"> (Standardwerte: kein Maschinenprofil)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="893"/>
        <source>; a changed profile applies at the next Connect</source>
        <translation>; ein geändertes Profil gilt ab dem nächsten Verbinden</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="919"/>
        <source>Emergency stop: cuts the platform&apos;s power stage at once. Afterwards: %1.</source>
        <translation>Not-Halt: schaltet die Endstufe der Plattform sofort ab. Danach: %1.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="921"/>
        <source>Emergency stop: halts the robot program at maximal deceleration. Afterwards: %1.</source>
        <translation>Not-Halt: hält das Roboterprogramm mit größter Verzögerung an. Danach: %1.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="926"/>
        <source>Resets the platform after a fault or an E-STOP; then Enable and Home again.</source>
        <translation>Setzt die Plattform nach einem Fehler oder NOT-HALT zurück; danach erneut „Aktivieren“ und „Referenzfahrt“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="927"/>
        <source>Resets the robot program after a fault or an E-STOP; it then takes moves again.</source>
        <translation>Setzt das Roboterprogramm nach einem Fehler oder NOT-HALT zurück; danach nimmt es wieder Fahrbefehle an.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="929"/>
        <source>Finds the home switch (0°); the drive must be enabled.</source>
        <translation>Sucht den Referenzschalter (0°); der Antrieb muss aktiviert sein.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="930"/>
        <source>Levels the platform (tilt 0°).</source>
        <translation>Richtet die Plattform waagerecht aus (Neigung 0°).</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="979"/>
        <source>unknown since %1</source>
        <translation>unbekannt seit %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="981"/>
        <source>not seen yet</source>
        <translation>noch nicht empfangen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="984"/>
        <source>%1 s ago</source>
        <translation>vor %1 s</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="993"/>
        <source>No plan: run a search or open a plan first.</source>
        <translation>Kein Plan: starten Sie zuerst eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="994"/>
        <source>Plan with %n region(s).</source>
        <translation>
            <numerusform>Plan mit %n Bereich.</numerusform>
            <numerusform>Plan mit %n Bereichen.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="996"/>
        <source>Sliced: a connected printer prints each region&apos;s G-code.</source>
        <translation>Slicing-Ergebnis vorhanden: ein verbundener Drucker druckt den G-Code jedes Bereichs.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="1004"/>
        <source>all %n region(s) printed: finished</source>
        <translation>
            <numerusform>%n Bereich gedruckt: abgeschlossen</numerusform>
            <numerusform>alle %n Bereiche gedruckt: abgeschlossen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="1006"/>
        <source>%1 of %2: %3</source>
        <translation>%1 von %2: %3</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="1008"/>
        <source> (%1, %2)</source>
        <translation> (%1, %2)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="1009"/>
        <source>; pausing after this region</source>
        <translation>; Pause nach diesem Bereich</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="386"/>
        <location filename="../ui/device/hardware_panel.cpp" line="798"/>
        <source>Restart step</source>
        <translation>Schritt neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="387"/>
        <source>Prints the current step again from the start of its G-code, once you have cleared the platform of what the interrupted print left.</source>
        <translation>Druckt den aktuellen Schritt noch einmal vom Anfang seines G-Codes, nachdem Sie die Plattform von dem befreit haben, was der unterbrochene Druck hinterlassen hat.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="720"/>
        <source>Start Run</source>
        <translation>Lauf starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="721"/>
        <source>The last run of this plan was aborted at step %1 of %2.</source>
        <translation>Der letzte Lauf dieses Plans wurde bei Schritt %1 von %2 abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="727"/>
        <source>Steps 1 to %1 were printed. Before the platform moves, make sure it is clear: take off what step %2 left half printed and anything in the platform&apos;s way.</source>
        <translation>Die Schritte 1 bis %1 wurden gedruckt. Bevor sich die Plattform bewegt, muss sie frei sein: entfernen Sie, was Schritt %2 halb gedruckt hinterlassen hat, und alles, was der Plattform im Weg ist.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="731"/>
        <source>Before the platform moves, make sure it is clear: take off what step 1 left half printed and anything in the platform&apos;s way.</source>
        <translation>Bevor sich die Plattform bewegt, muss sie frei sein: entfernen Sie, was Schritt 1 halb gedruckt hinterlassen hat, und alles, was der Plattform im Weg ist.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="735"/>
        <source>Platform Clear: &amp;Resume from Step %1</source>
        <translation>Plattform frei: ab Schritt %1 &amp;fortsetzen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="738"/>
        <source>Platform Clear: &amp;Start from Step 1</source>
        <translation>Plattform frei: ab Schritt 1 &amp;starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="751"/>
        <source>Start run refused: the plan changed since the question was asked; press Start run again.</source>
        <translation>„Lauf starten“ abgelehnt: der Plan hat sich seit der Frage geändert; drücken Sie erneut „Lauf starten“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="764"/>
        <source>%1 has no job of step %2 any more: it may have restarted, so there is nothing to resume. Restart step prints step %2 again from its start, once you have cleared the platform of what the interrupted print left. Or finish the region by hand and press Region done, or Abort.</source>
        <translation>%1 hat keinen Auftrag von Schritt %2 mehr: er wurde vielleicht neu gestartet, daher gibt es nichts fortzusetzen. „Schritt neu starten“ druckt Schritt %2 noch einmal von Anfang an, nachdem Sie die Plattform von dem befreit haben, was der unterbrochene Druck hinterlassen hat. Oder stellen Sie den Bereich von Hand fertig und drücken Sie „Bereich fertig“, oder „Abbrechen“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="770"/>
        <source>Restart Step %1</source>
        <translation>Schritt %1 neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="780"/>
        <source>Restart Step</source>
        <translation>Schritt neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="781"/>
        <source>Print step %1 again from its start?</source>
        <translation>Schritt %1 noch einmal von Anfang an drucken?</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="783"/>
        <source>The printer lost the job of step %1 part way. Before it prints the step again, take off what the interrupted print left of region %1 (the regions printed before it stay) and make sure the nozzle&apos;s way is clear.</source>
        <translation>Der Drucker hat den Auftrag von Schritt %1 mittendrin verloren. Bevor er den Schritt noch einmal druckt, entfernen Sie, was der unterbrochene Druck von Bereich %1 hinterlassen hat (die davor gedruckten Bereiche bleiben), und sorgen Sie dafür, dass der Weg der Düse frei ist.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="787"/>
        <source>Platform Clear: &amp;Restart Step %1</source>
        <translation>Plattform frei: Schritt %1 &amp;neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="497"/>
        <source>the robot cell</source>
        <translation>die Roboterzelle</translation>
    </message>
</context>
<context>
    <name>multidir::ui::JgChart</name>
    <message>
        <location filename="../ui/panels/jg_chart.cpp" line="27"/>
        <source>Level</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <location filename="../ui/panels/jg_chart.cpp" line="32"/>
        <source>Best J_G (mm²)</source>
        <translation>Bestes J_G (mm²)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::JobTimeline</name>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Region</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Started</source>
        <translation>Beginn</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="106"/>
        <source>Ended</source>
        <translation>Ende</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="133"/>
        <source>waiting</source>
        <translation>wartend</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="135"/>
        <source>moving</source>
        <translation>in Bewegung</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="137"/>
        <source>settling</source>
        <translation>Beruhigungszeit</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="139"/>
        <source>printing</source>
        <translation>Druck läuft</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="141"/>
        <source>done</source>
        <translation>fertig</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="143"/>
        <source>paused</source>
        <translation>pausiert</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="145"/>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="147"/>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../ui/device/job_timeline.cpp" line="157"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MachineKind</name>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="9"/>
        <source>3-DOF</source>
        <translation>3-DOF</translation>
    </message>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="11"/>
        <source>rotary platform (4-DOF)</source>
        <translation>Drehplattform (4-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="13"/>
        <source>tilting (5-DOF)</source>
        <translation>kippend (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/common/machine_kind_text.cpp" line="15"/>
        <source>printed apart</source>
        <translation>getrennt gedruckt</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MachinePanel</name>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="32"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="48"/>
        <source>3-DOF: fixed printing direction</source>
        <translation>3-DOF: feste Druckrichtung</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="49"/>
        <source>4-DOF: rotary platform</source>
        <translation>4-DOF: Drehplattform</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="50"/>
        <source>5-DOF: tilting robot arm</source>
        <translation>5-DOF: kippender Roboterarm</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="57"/>
        <source>Rotary platform (4-DOF)</source>
        <translation>Drehplattform (4-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="60"/>
        <source>The axis the platform turns about, as x,y,z or x, -y, +z; it must lie in the platform plane (perpendicular to up)</source>
        <translation>Die Achse, um die sich die Plattform dreht, als x,y,z oder x, -y, +z; sie muss in der Plattformebene liegen (senkrecht zu oben)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="62"/>
        <source>Pick on platform</source>
        <translation>Auf Plattform wählen</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="65"/>
        <source>Click two points on the platform in the 3D view: the axis runs from the first to the second. Esc or this button again cancels.</source>
        <translation>Klicken Sie in der 3D-Ansicht auf zwei Punkte der Plattform: die Achse verläuft vom ersten zum zweiten. Esc oder ein erneuter Klick auf diese Schaltfläche bricht ab.</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="70"/>
        <source>The stepper&apos;s resolution: only multiples of this angle can be reached</source>
        <translation>Auflösung des Schrittmotors: nur Vielfache dieses Winkels sind erreichbar</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="72"/>
        <source>Rotation axis:</source>
        <translation>Drehachse:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="74"/>
        <source>Minimal angle:</source>
        <translation>Kleinster Winkel:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="75"/>
        <source>Maximal angle:</source>
        <translation>Größter Winkel:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="76"/>
        <source>Angle step:</source>
        <translation>Winkelschritt:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="78"/>
        <source>Tilting arm (5-DOF)</source>
        <translation>Kipparm (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="80"/>
        <source>How far the arm can tilt the platform away from up</source>
        <translation>Wie weit der Arm die Plattform aus der Senkrechten kippen kann</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="82"/>
        <source>Tilt limit:</source>
        <translation>Kippgrenze:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="88"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="89"/>
        <source>model footprint</source>
        <translation>Modellgrundfläche</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="91"/>
        <source>Radius of the platform disc that no clipping plane may cut; 0 uses the model&apos;s footprint plus a margin</source>
        <translation>Radius der Plattformscheibe, die keine Schnittebene schneiden darf; 0 nimmt die Grundfläche des Modells plus einen Rand</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="101"/>
        <source>Machine:</source>
        <translation>Maschine:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="102"/>
        <source>Platform radius:</source>
        <translation>Plattformradius:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="212"/>
        <source>The rotation axis &quot;%1&quot; cannot be read: type three numbers x,y,z or an axis such as x or -y.</source>
        <translation>Die Drehachse „%1“ ist nicht lesbar: Geben Sie drei Zahlen x,y,z oder eine Achse wie x oder -y ein.</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="217"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="51"/>
        <source>5-DOF: robot arm under a fixed extruder</source>
        <translation>5-DOF: Roboterarm unter einem feststehenden Extruder</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="54"/>
        <source>Apart (plain printer, parts joined by dowels)</source>
        <translation>Getrennt (einfacher Drucker, Teile mit Dübeln verbunden)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="95"/>
        <source>MultiDir Studio</source>
        <translation>MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="126"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="127"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="145"/>
        <source>Show a plan saved earlier (a folder with plan.json)</source>
        <translation>Einen früher gespeicherten Plan anzeigen (ein Ordner mit plan.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="146"/>
        <source>&amp;Export plan...</source>
        <translation>Plan &amp;exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="148"/>
        <source>Save the plan shown: plan.json and one STL per region</source>
        <translation>Den angezeigten Plan speichern: plan.json und eine STL-Datei je Bereich</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="159"/>
        <source>&amp;Load machine profile...</source>
        <translation>Maschinenprofil &amp;laden...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="164"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="168"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="169"/>
        <source>&amp;Fit to View</source>
        <translation>In Ansicht ein&amp;passen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="171"/>
        <source>Show the &amp;model (hide the plan)</source>
        <translation>&amp;Modell zeigen (Plan ausblenden)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="179"/>
        <location filename="../ui/main_window.cpp" line="747"/>
        <source>&amp;Search</source>
        <translation>&amp;Suche</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="180"/>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="184"/>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="256"/>
        <source>Overhangs</source>
        <translation>Überhänge</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="257"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="258"/>
        <source>Search</source>
        <translation>Suche</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="267"/>
        <source>Plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="322"/>
        <source>Hardware</source>
        <translation>Hardware</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="360"/>
        <source>Printing direction</source>
        <translation>Druckrichtung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="363"/>
        <source>Up:</source>
        <translation>Oben:</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="370"/>
        <source>The direction the model is printed along: the platform is below, overhangs are measured against it</source>
        <translation>Die Richtung, in der das Modell gedruckt wird: die Plattform liegt darunter, Überhänge werden daran gemessen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="375"/>
        <source>+X</source>
        <translation>+X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="375"/>
        <source>-X</source>
        <translation>-X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="376"/>
        <source>+Y</source>
        <translation>+Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="376"/>
        <source>-Y</source>
        <translation>-Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="377"/>
        <source>+Z</source>
        <translation>+Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="377"/>
        <source>-Z</source>
        <translation>-Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="130"/>
        <source>Open a mesh file (STL, OBJ, OFF or PLY) or a MultiDir project</source>
        <translation>Eine Netzdatei (STL, OBJ, OFF oder PLY) oder ein MultiDir-Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="157"/>
        <source>Save the 3D view as shown to a PNG or JPEG file</source>
        <translation>Die 3D-Ansicht wie angezeigt als PNG- oder JPEG-Datei speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="161"/>
        <source>Save machine pro&amp;file...</source>
        <translation>Maschinenprofil &amp;speichern...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="173"/>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="197"/>
        <source>S&amp;lice the plan...</source>
        <translation>Plan s&amp;licen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="200"/>
        <source>Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)</source>
        <translation>Jeden Schritt des angezeigten Plans mit seinen Stützen in G-Code slicen (PrusaSlicer)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="214"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="215"/>
        <source>&amp;About MultiDir Studio</source>
        <translation>Ü&amp;ber MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="222"/>
        <source>About MultiDir Studio</source>
        <translation>Über MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="223"/>
        <source>MultiDir Studio %1</source>
        <translation>MultiDir Studio %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="225"/>
        <source>Plans multi-directional 3D prints: cuts a model by planes into regions, each printed along its own direction, and drives the machine that prints them.

Qt %1</source>
        <translation>Plant mehrrichtige 3D-Drucke: zerschneidet ein Modell mit Ebenen in Bereiche, die jeweils entlang ihrer eigenen Richtung gedruckt werden, und steuert die Maschine, die sie druckt.

Qt %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="324"/>
        <source>Emergency stop</source>
        <translation>Not-Halt</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="442"/>
        <source>The pose search was stopped; its result is dropped.</source>
        <translation>Die Posensuche wurde angehalten; ihr Ergebnis wird verworfen.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="448"/>
        <source>The search was stopped; its result is dropped.</source>
        <translation>Die Suche wurde angehalten; ihr Ergebnis wird verworfen.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="462"/>
        <source>Open Model or Project</source>
        <translation>Modell oder Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="463"/>
        <source>Meshes and projects (*.stl *.obj *.off *.ply *.multidir);;Meshes (*.stl *.obj *.off *.ply);;MultiDir projects (*.multidir);;All files (*)</source>
        <translation>Netze und Projekte (*.stl *.obj *.off *.ply *.multidir);;Netze (*.stl *.obj *.off *.ply);;MultiDir-Projekte (*.multidir);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="500"/>
        <source>%1, %2, %3</source>
        <translation>%1; %2; %3</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="507"/>
        <location filename="../ui/main_window.cpp" line="513"/>
        <source>Pose: %1</source>
        <translation>Pose: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="508"/>
        <source>Custom (%1, %2, %3)</source>
        <translation>Benutzerdefiniert (%1, %2, %3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="579"/>
        <source>%1 - MultiDir Studio</source>
        <translation>%1 - MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="583"/>
        <source>Repaired on load: %1</source>
        <translation>Beim Laden repariert: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="597"/>
        <source>Could not open %1: %2</source>
        <translation>%1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="601"/>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="605"/>
        <source>%1 is still open.</source>
        <translation>%1 ist weiterhin geöffnet.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="628"/>
        <location filename="../ui/main_window.cpp" line="645"/>
        <source>No model</source>
        <translation>Kein Modell</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="638"/>
        <source>Triangles: %1</source>
        <translation>Dreiecke: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="639"/>
        <source>Volume: %1 mm³</source>
        <translation>Volumen: %1 mm³</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="653"/>
        <source>Risky area unavailable</source>
        <translation>Risikofläche nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="661"/>
        <source>Risky area (%1 up): %2 mm²</source>
        <translation>Risikofläche (%1 oben): %2 mm²</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="663"/>
        <source>Area of the faces that overhang by more than %1° for this up direction</source>
        <translation>Fläche der Dreiecke, die bei dieser Aufwärtsrichtung um mehr als %1° überhängen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="682"/>
        <location filename="../ui/main_window.cpp" line="705"/>
        <location filename="../ui/main_window_pose.cpp" line="38"/>
        <location filename="../ui/main_window_pose.cpp" line="55"/>
        <source>Open a model first.</source>
        <translation>Öffnen Sie zuerst ein Modell.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="684"/>
        <location filename="../ui/main_window_pose.cpp" line="40"/>
        <source>Fix the machine first: %1</source>
        <translation>Korrigieren Sie zuerst die Maschine: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="686"/>
        <location filename="../ui/main_window.cpp" line="704"/>
        <source>A pose search is running: wait for it or cancel it.</source>
        <translation>Eine Posensuche läuft: warten Sie, bis sie fertig ist, oder brechen Sie sie ab.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="703"/>
        <source>A search is already running.</source>
        <translation>Eine Suche läuft bereits.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="710"/>
        <location filename="../ui/main_window_pose.cpp" line="63"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="714"/>
        <source>Cannot search: %1</source>
        <translation>Suche nicht möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="715"/>
        <source>Cannot search.</source>
        <translation>Suche nicht möglich.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="729"/>
        <source>Searching %1...</source>
        <translation>Durchsuche %1...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="764"/>
        <source>Cancelling the search...</source>
        <translation>Suche wird abgebrochen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="777"/>
        <source>The search result was dropped: the model or its up direction changed.</source>
        <translation>Das Suchergebnis wurde verworfen: das Modell oder seine Aufwärtsrichtung hat sich geändert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="792"/>
        <source>Search cancelled: showing the best plan found so far.</source>
        <translation>Suche abgebrochen: der bisher beste Plan wird angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="793"/>
        <source>Search finished.</source>
        <translation>Suche beendet.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="813"/>
        <source>Search failed: %1</source>
        <translation>Suche fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="849"/>
        <source>Growing supports for the plan...</source>
        <translation>Stützen für den Plan werden erzeugt...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="861"/>
        <source>Supports grown for the plan.</source>
        <translation>Stützen für den Plan erzeugt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="931"/>
        <source>There is no plan to export: run a search first.</source>
        <translation>Es gibt keinen Plan zum Exportieren: starten Sie zuerst eine Suche.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="934"/>
        <source>The supports of this plan are still being grown: export it again when the status bar says they are ready.</source>
        <translation>Die Stützen dieses Plans werden noch erzeugt: exportieren Sie ihn erneut, sobald die Statusleiste meldet, dass sie fertig sind.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="938"/>
        <source>Could not create the folder %1: check that its parent exists and can be written.</source>
        <translation>Der Ordner %1 konnte nicht angelegt werden: prüfen Sie, ob der übergeordnete Ordner existiert und beschreibbar ist.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="968"/>
        <source>Could not export the plan to %1: %2 (%3)</source>
        <translation>Der Plan konnte nicht nach %1 exportiert werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="974"/>
        <source>Plan exported to %1 without supports although %2 mm² of risky area remains: %3</source>
        <translation>Plan ohne Stützen nach %1 exportiert, obwohl %2 mm² Risikofläche verbleiben: %3</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="976"/>
        <source>no supports were grown for it.</source>
        <translation>für ihn wurden keine Stützen erzeugt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="981"/>
        <source>Plan exported to %1.</source>
        <translation>Plan nach %1 exportiert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="988"/>
        <source>Could not open the plan %1: %2 (%3)</source>
        <translation>Der Plan %1 konnte nicht geöffnet werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1035"/>
        <source>Machine profile saved to %1.</source>
        <translation>Maschinenprofil unter %1 gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1047"/>
        <source>Machine profile %1 loaded.</source>
        <translation>Maschinenprofil %1 geladen.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1056"/>
        <source>Export Plan to Folder</source>
        <translation>Plan in Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1056"/>
        <source>-plan</source>
        <translation>-Plan</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1057"/>
        <source>Plan folders (*)</source>
        <translation>Planordner (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1063"/>
        <location filename="../ui/main_window.cpp" line="1065"/>
        <source>Export Plan</source>
        <translation>Plan exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1076"/>
        <source>Screenshot saved to %1.</source>
        <translation>Bildschirmfoto unter %1 gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1081"/>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1082"/>
        <source>JPEG images (*.jpg *.jpeg)</source>
        <translation>JPEG-Bilder (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1085"/>
        <location filename="../ui/main_window.cpp" line="1093"/>
        <source>Export Screenshot</source>
        <translation>Bildschirmfoto exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1098"/>
        <source>Open Plan Folder</source>
        <translation>Planordner öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="433"/>
        <source>Open Plan</source>
        <translation>Plan öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="133"/>
        <source>Sa&amp;mples</source>
        <translation>Beis&amp;piele</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="143"/>
        <source>Open pla&amp;n...</source>
        <translation>Pla&amp;n öffnen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="150"/>
        <source>Export &amp;G-code...</source>
        <translation>&amp;G-Code exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="152"/>
        <source>Save the sliced plan&apos;s G-code (step-NN.gcode, job.gcode) and its print job</source>
        <translation>Den beim Slicen erzeugten G-Code des Plans (step-NN.gcode, job.gcode) und seinen Druckauftrag speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Export Screens&amp;hot...</source>
        <translation>Bildschirmfoto expo&amp;rtieren...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1104"/>
        <location filename="../ui/main_window.cpp" line="1110"/>
        <source>Save Machine Profile</source>
        <translation>Maschinenprofil speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1106"/>
        <source>Machine profiles (*.json)</source>
        <translation>Maschinenprofile (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1114"/>
        <location filename="../ui/main_window.cpp" line="1121"/>
        <source>Load Machine Profile</source>
        <translation>Maschinenprofil laden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1116"/>
        <source>Machine profiles (*.json);;All files (*)</source>
        <translation>Maschinenprofile (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="1134"/>
        <source>Loading %1...</source>
        <translation>Lade %1...</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="22"/>
        <source>Edit plan</source>
        <translation>Plan bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="60"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="62"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../ui/main_window_editing.cpp" line="65"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="42"/>
        <location filename="../ui/main_window_pose.cpp" line="54"/>
        <source>A search is running: wait for it or cancel it.</source>
        <translation>Eine Suche läuft: warten Sie, bis sie fertig ist, oder brechen Sie sie ab.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="53"/>
        <source>A pose search is already running.</source>
        <translation>Eine Posensuche läuft bereits.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="56"/>
        <source>This plan was opened without its model: open the model.</source>
        <translation>Dieser Plan wurde ohne sein Modell geöffnet: öffnen Sie das Modell.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="67"/>
        <source>Cannot find the best pose: %1</source>
        <translation>Die beste Pose kann nicht gesucht werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="68"/>
        <source>Cannot find the best pose.</source>
        <translation>Die beste Pose kann nicht gesucht werden.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="77"/>
        <source>Finding the best pose for %1...</source>
        <translation>Beste Pose für %1 wird gesucht...</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="85"/>
        <source>Cancelling the pose search...</source>
        <translation>Posensuche wird abgebrochen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="98"/>
        <source>The pose search result was dropped: the model or its up direction changed.</source>
        <translation>Das Ergebnis der Posensuche wurde verworfen: das Modell oder seine Aufwärtsrichtung hat sich geändert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="108"/>
        <source>Pose search cancelled: the poses that finished are listed; the plan shown is unchanged.</source>
        <translation>Posensuche abgebrochen: die fertigen Posen sind aufgelistet; der angezeigte Plan bleibt unverändert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="112"/>
        <source>Best pose found.</source>
        <translation>Beste Pose gefunden.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="122"/>
        <source>Pose search cancelled before any pose finished: the plan shown is unchanged.</source>
        <translation>Posensuche abgebrochen, bevor eine Pose fertig war: der angezeigte Plan bleibt unverändert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="124"/>
        <source>Pose search failed: %1</source>
        <translation>Posensuche fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="140"/>
        <source>Showing pose %1 (up %2, %3, %4): the project is unchanged. &quot;Use this pose&quot; makes it the model&apos;s up; &quot;Show current up&quot; goes back.</source>
        <translation>Pose %1 wird angezeigt (Aufwärtsrichtung %2, %3, %4): das Projekt bleibt unverändert. „Diese Pose verwenden“ macht sie zur Aufwärtsrichtung des Modells; „Aktuelle Aufwärtsrichtung zeigen“ kehrt zurück.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="187"/>
        <source>This pose belongs to another model: find the best pose again.</source>
        <translation>Diese Pose gehört zu einem anderen Modell: suchen Sie die beste Pose erneut.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="203"/>
        <source>The model now stands on the best pose; its plan is shown.</source>
        <translation>Das Modell steht jetzt in der besten Pose; sein Plan wird angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window_pose.cpp" line="206"/>
        <source>The model now stands on pose %1; searching its plan...</source>
        <translation>Das Modell steht jetzt in Pose %1; sein Plan wird gesucht...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="743"/>
        <source>Replace the Edited Plan</source>
        <translation>Bearbeiteten Plan ersetzen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="744"/>
        <source>The plan shown has edits that are not saved.</source>
        <translation>Der angezeigte Plan hat Änderungen, die nicht gespeichert sind.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="746"/>
        <source>A new search replaces it; Edit &gt; Undo brings it back. Search now?</source>
        <translation>Eine neue Suche ersetzt ihn; Bearbeiten &gt; Rückgängig holt ihn zurück. Jetzt suchen?</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="784"/>
        <source>Search cancelled: its best plan so far (J_G %1 mm²) is worse than the plan shown (J_G %2 mm²), which is kept.</source>
        <translation>Suche abgebrochen: ihr bisher bester Plan (J_G %1 mm²) ist schlechter als der angezeigte Plan (J_G %2 mm²), der bleibt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="904"/>
        <source>Print Run Under Way</source>
        <translation>Drucklauf läuft</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="905"/>
        <source>A print run is under way: step %1.</source>
        <translation>Ein Drucklauf läuft: Schritt %1.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="908"/>
        <source>Quitting stops the platform and the printer first: the run is aborted (Start run offers to resume it from the step it stopped at). Stop the devices and quit?</source>
        <translation>Beim Beenden werden zuerst die Plattform und der Drucker angehalten: der Lauf wird abgebrochen („Lauf starten“ bietet an, ihn bei dem Schritt fortzusetzen, bei dem er stehen blieb). Geräte anhalten und beenden?</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="910"/>
        <source>S&amp;top the Devices and Quit</source>
        <translation>Geräte an&amp;halten und beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="203"/>
        <source>Print &amp;apart...</source>
        <translation>&amp;Getrennt drucken...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="209"/>
        <source>Print the plan shown on an ordinary printer: every region a part, joined by dowels</source>
        <translation>Den angezeigten Plan auf einem gewöhnlichen Drucker drucken: jeder Bereich ein Teil, durch Dübel verbunden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="272"/>
        <source>Print apart</source>
        <translation>Getrennt drucken</translation>
    </message>
    <message>
        <location filename="../ui/main_window_cell.cpp" line="23"/>
        <source>Cell view</source>
        <translation>Zellenansicht</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MeshViewerWidget</name>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="421"/>
        <source>Open a model (%1) or File &gt; Samples</source>
        <translation>Modell öffnen (%1) oder Datei &gt; Beispiele</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="629"/>
        <source>%1, %2, %3 mm</source>
        <translation>%1; %2; %3 mm</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="633"/>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="635"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="636"/>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="637"/>
        <source>Distance: %1</source>
        <translation>Abstand: %1</translation>
    </message>
    <message>
        <location filename="../ui/viewer/mesh_viewer_widget.cpp" line="640"/>
        <source>Click a second point on the model (Esc ends measuring)</source>
        <translation>Einen zweiten Punkt auf dem Modell anklicken (Esc beendet das Messen)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="29"/>
        <source>&amp;Front</source>
        <translation>&amp;Vorne</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="29"/>
        <source>Look at the model&apos;s front</source>
        <translation>Das Modell von vorne ansehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="31"/>
        <source>&amp;Back</source>
        <translation>&amp;Hinten</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="31"/>
        <source>Look at the model&apos;s back</source>
        <translation>Das Modell von hinten ansehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="33"/>
        <source>&amp;Left</source>
        <translation>&amp;Links</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="33"/>
        <source>Look at the model&apos;s left side</source>
        <translation>Die linke Seite des Modells ansehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="35"/>
        <source>&amp;Right</source>
        <translation>&amp;Rechts</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="36"/>
        <source>Look at the model&apos;s right side</source>
        <translation>Die rechte Seite des Modells ansehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="37"/>
        <source>&amp;Top</source>
        <translation>&amp;Oben</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="38"/>
        <source>Look down the printing direction (Up)</source>
        <translation>Entgegen der Druckrichtung (Oben) auf das Modell sehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="39"/>
        <source>Botto&amp;m</source>
        <translation>U&amp;nten</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="40"/>
        <source>Look up at the model from below the platform</source>
        <translation>Das Modell von unterhalb der Plattform ansehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="41"/>
        <source>&amp;Isometric</source>
        <translation>&amp;Isometrisch</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="42"/>
        <source>Look at the front, the right and the top equally</source>
        <translation>Vorder-, rechte und Oberseite gleich stark verkürzt ansehen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="45"/>
        <source>&amp;Standard views</source>
        <translation>&amp;Standardansichten</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="59"/>
        <source>&amp;Orthographic</source>
        <translation>&amp;Orthografisch</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="64"/>
        <source>Parallel projection: equal lengths look equal wherever they are (5)</source>
        <translation>Parallelprojektion: gleiche Längen erscheinen überall gleich lang (5)</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="68"/>
        <source>M&amp;easure distance</source>
        <translation>Abstand m&amp;essen</translation>
    </message>
    <message>
        <location filename="../ui/viewer/view_actions.cpp" line="73"/>
        <source>Click two points on the model: their coordinates and the distance between them (M; Esc ends)</source>
        <translation>Zwei Punkte auf dem Modell anklicken: ihre Koordinaten und ihr Abstand (M; Esc beendet)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ModelLoader</name>
    <message>
        <location filename="../ui/jobs/model_loader.cpp" line="51"/>
        <source>Not enough memory to load this model.</source>
        <translation>Nicht genug Speicher, um dieses Modell zu laden.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/model_loader.cpp" line="54"/>
        <location filename="../ui/jobs/model_loader.cpp" line="58"/>
        <source>Unexpected error while loading.</source>
        <translation>Unerwarteter Fehler beim Laden.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::OverhangPanel</name>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="29"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="32"/>
        <source>Maximal self-supporting angle: faces that lean over by more than this from the printing direction need support</source>
        <translation>Größter selbsttragender Winkel: Flächen, die stärker als dieser Winkel überhängen, brauchen Stützen</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="65"/>
        <source>Risky faces (need support when printed along the up direction)</source>
        <translation>Dreiecke der Risikofläche (brauchen Stützen beim Druck in Aufwärtsrichtung)</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="68"/>
        <source>Max. overhang angle α:</source>
        <translation>Max. Überhangwinkel α:</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="69"/>
        <source>Risky area:</source>
        <translation>Risikofläche:</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="70"/>
        <source>Risky faces:</source>
        <translation>Dreiecke der Risikofläche:</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="75"/>
        <source>No model</source>
        <translation>Kein Modell</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="83"/>
        <source>%1 mm²</source>
        <translation>%1 mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="85"/>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="90"/>
        <source>unavailable</source>
        <translation>nicht verfügbar</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PictureFile</name>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="32"/>
        <source>Could not save %1: there is no picture to save.</source>
        <translation>%1 konnte nicht gespeichert werden: es gibt kein Bild zum Speichern.</translation>
    </message>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="35"/>
        <source>Could not save %1: give the file name the extension .png or .jpg.</source>
        <translation>%1 konnte nicht gespeichert werden: geben Sie dem Dateinamen die Endung .png oder .jpg.</translation>
    </message>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="42"/>
        <source>Could not save %1: the file cannot be written there; check that its folder exists and may be written to.</source>
        <translation>%1 konnte nicht gespeichert werden: die Datei kann dort nicht geschrieben werden; prüfen Sie, ob ihr Ordner existiert und beschreibbar ist.</translation>
    </message>
    <message>
        <location filename="../ui/common/picture_file.cpp" line="45"/>
        <source>Could not save %1: %2</source>
        <translation>%1 konnte nicht gespeichert werden: %2</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PlanPanel</name>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="66"/>
        <location filename="../ui/panels/plan_panel.cpp" line="200"/>
        <source>No plan yet: run a search or open a plan.</source>
        <translation>Noch kein Plan: starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Region</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Volume (mm³)</source>
        <translation>Volumen (mm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Risky (mm²)</source>
        <translation>Risikofläche (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="72"/>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="73"/>
        <source>Machine angles</source>
        <translation>Maschinenwinkel</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="73"/>
        <source>Supports (mm³)</source>
        <translation>Stützen (mm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="84"/>
        <source>Printing directions</source>
        <translation>Druckrichtungen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="87"/>
        <source>Clipping planes</source>
        <translation>Schnittebenen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="89"/>
        <source>Supports</source>
        <translation>Stützen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="92"/>
        <source>The tree supports grown for the risky area the plan leaves, in one colour</source>
        <translation>Die Baumstützen, die für die vom Plan verbleibende Risikofläche erzeugt wurden, in einer Farbe</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="93"/>
        <source>Turn the view as the machine turns the part</source>
        <translation>Ansicht drehen, wie die Maschine das Teil dreht</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="98"/>
        <source>Moves the regions apart along their printing directions</source>
        <translation>Schiebt die Bereiche entlang ihrer Druckrichtungen auseinander</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="105"/>
        <source>Previous region</source>
        <translation>Vorheriger Bereich</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="108"/>
        <source>Next region</source>
        <translation>Nächster Bereich</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="117"/>
        <source>Show:</source>
        <translation>Anzeigen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="120"/>
        <source>Exploded view:</source>
        <translation>Explosionsansicht:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="121"/>
        <source>Printed up to:</source>
        <translation>Gedruckt bis:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="159"/>
        <source>none (fixed)</source>
        <translation>keine (fest)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="161"/>
        <source>rotary %1°</source>
        <translation>Drehung %1°</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="165"/>
        <source>tilt %1°, azimuth %2°</source>
        <translation>Neigung %1°, Azimut %2°</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="173"/>
        <location filename="../ui/panels/plan_panel.cpp" line="176"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="174"/>
        <source>No supports were grown for this plan</source>
        <translation>Für diesen Plan wurden keine Stützen erzeugt</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/plan_panel.cpp" line="178"/>
        <source>%n region(s); J_G %1 mm² before, %2 mm² after.</source>
        <translation>
            <numerusform>%n Bereich; J_G vorher %1 mm², nachher %2 mm².</numerusform>
            <numerusform>%n Bereiche; J_G vorher %1 mm², nachher %2 mm².</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="233"/>
        <source>of %1</source>
        <translation>von %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="50"/>
        <source>1 contact on risky faces</source>
        <translation>1 Kontakt auf der Risikofläche</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="51"/>
        <source>%1 contacts on risky faces</source>
        <translation>%1 Kontakte auf der Risikofläche</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="53"/>
        <source>1 lowest point</source>
        <translation>1 tiefster Punkt</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="54"/>
        <source>%1 lowest points</source>
        <translation>%1 tiefste Punkte</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="56"/>
        <source>%1 mm of downward edges</source>
        <translation>%1 mm nach unten weisende Kanten</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="58"/>
        <source>struts of later regions (%1 mm³)</source>
        <translation>Streben späterer Bereiche (%1 mm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="73"/>
        <source>Supports hold up</source>
        <translation>Von Stützen getragen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="75"/>
        <source>Risky faces are the area J_G counts. Lowest points and downward edges have no area but still print in air; struts of regions printed later go on through this region&apos;s space.</source>
        <translation>Die Dreiecke der Risikofläche sind die Fläche, die J_G zählt. Tiefste Punkte und nach unten weisende Kanten haben keine Fläche, werden aber trotzdem in der Luft gedruckt; Streben später gedruckter Bereiche führen durch den Raum dieses Bereichs.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PlaneEditPanel</name>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="89"/>
        <source>Plane</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="89"/>
        <source>Normal</source>
        <translation>Normale</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="89"/>
        <source>Offset (mm)</source>
        <translation>Versatz (mm)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="91"/>
        <source>Planes are numbered in printing order, like the regions: plane k is the base of region k + 1</source>
        <translation>Ebenen sind wie die Bereiche in Druckreihenfolge nummeriert: Ebene k ist die Grundfläche von Bereich k + 1</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="105"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="107"/>
        <source>Distance of the plane from the origin along its normal</source>
        <translation>Abstand der Ebene vom Ursprung entlang ihrer Normalen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="110"/>
        <source>Moves the plane along its normal across what is left of the model</source>
        <translation>Verschiebt die Ebene entlang ihrer Normalen über den verbleibenden Teil des Modells</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="113"/>
        <source>Offset:</source>
        <translation>Versatz:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="125"/>
        <source>Tilt:</source>
        <translation>Neigung:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="126"/>
        <source>Azimuth:</source>
        <translation>Azimut:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="135"/>
        <source>Rotary angle:</source>
        <translation>Drehwinkel:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="138"/>
        <source>&amp;Add plane</source>
        <translation>Ebene &amp;hinzufügen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="141"/>
        <source>Splits the piece above the selected plane in two (or, with no plane selected, cuts what is left on the platform at mid-height)</source>
        <translation>Teilt das Stück über der gewählten Ebene in zwei (oder schneidet, wenn keine Ebene gewählt ist, den auf der Plattform verbleibenden Teil auf halber Höhe)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="143"/>
        <source>&amp;Delete plane</source>
        <translation>Ebene &amp;löschen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="145"/>
        <source>Updating the plan...</source>
        <translation>Plan wird aktualisiert...</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="261"/>
        <source>No plan to edit: run a search or open a plan.</source>
        <translation>Kein Plan zum Bearbeiten: starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="263"/>
        <source>This plan is shown without its model: open the model it was made from to edit it.</source>
        <translation>Dieser Plan wird ohne sein Modell angezeigt: öffnen Sie das Modell, aus dem er erstellt wurde, um ihn zu bearbeiten.</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="265"/>
        <source>Select a plane to move, tilt or delete it. Every change can be undone (Ctrl+Z).</source>
        <translation>Wählen Sie eine Ebene, um sie zu verschieben, zu neigen oder zu löschen. Jede Änderung lässt sich rückgängig machen (Strg+Z).</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="278"/>
        <source>J_G before: %1 mm² (the whole model printed along up)
J_G after: %2 mm² (%3 mm² before editing)</source>
        <translation>J_G vorher: %1 mm² (ganzes Modell in Aufwärtsrichtung gedruckt)
J_G nachher: %2 mm² (%3 mm² vor der Bearbeitung)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plane_edit_panel.cpp" line="425"/>
        <source>Tilting turns the plane about the middle of its cut, so its offset (measured from the origin along the normal) went from %1 mm to %2 mm.</source>
        <translation>Beim Neigen dreht sich die Ebene um die Mitte ihrer Schnittfläche, daher hat sich ihr Versatz (vom Ursprung entlang der Normalen gemessen) von %1 mm auf %2 mm geändert.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PoseSearchBox</name>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="31"/>
        <source>given up</source>
        <translation>vorgegeben</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="32"/>
        <source>resting</source>
        <translation>Ruhelage</translation>
    </message>
    <message>
        <source>sampled</source>
        <translation type="vanished">abgetastet</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="39"/>
        <source>Best pose</source>
        <translation>Beste Pose</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="46"/>
        <source>Poses tried: the current up and the poses the model stands in on its own</source>
        <translation>Probierte Posen: die aktuelle Aufwärtsrichtung und die Posen, in denen das Modell von selbst steht</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="57"/>
        <source>Find best pose</source>
        <translation>Beste Pose finden</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="59"/>
        <location filename="../ui/panels/pose_search_box.cpp" line="140"/>
        <source>Try how the model could stand on the platform, each pose with its own decomposition, and keep the one with the least risky area left</source>
        <translation>Ausprobieren, wie das Modell auf der Plattform stehen könnte, jede Pose mit ihrer eigenen Zerlegung, und die mit der kleinsten verbleibenden Risikofläche behalten</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="61"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Up</source>
        <translation>Oben</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Contact (mm²)</source>
        <translation>Auflage (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="74"/>
        <source>Margin (mm)</source>
        <translation>Reserve (mm)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="77"/>
        <source>Area of the patch of the model&apos;s convex hull that stands on the platform in this pose</source>
        <translation>Fläche des Stücks der konvexen Hülle des Modells, das in dieser Pose auf der Plattform steht</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="79"/>
        <source>How far inside that patch the centre of mass falls: the model stands only when it is positive</source>
        <translation>Wie weit der Schwerpunkt innerhalb dieser Fläche liegt: das Modell steht nur, wenn der Wert positiv ist</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>Risky area (mm²)</source>
        <translation>Risikofläche (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="51"/>
        <source>Poses given the full search with the Search tab&apos;s settings: the current up first, then the best-scored others. The others are scored with a quick greedy plan, except those ruled out: poses no plan of which could beat the current up&apos;s</source>
        <translation>Posen, die die volle Suche mit den Einstellungen der Registerkarte „Suche“ erhalten: zuerst die aktuelle Aufwärtsrichtung, dann die am besten bewerteten anderen. Die übrigen werden mit einem schnellen gierigen Plan bewertet, außer den ausgeschlossenen: Posen, von denen kein Plan den der aktuellen Aufwärtsrichtung schlagen könnte</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>J_G (mm²)</source>
        <translation>J_G (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>Regions</source>
        <translation>Bereiche</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="75"/>
        <source>Search</source>
        <translation>Suche</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="82"/>
        <source>Risky area of the whole model printed along this up alone (J_G before)</source>
        <translation>Risikofläche des ganzen Modells, allein in dieser Aufwärtsrichtung gedruckt (J_G vorher)</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="83"/>
        <source>J_G of the plan found for this pose</source>
        <translation>J_G des für diese Pose gefundenen Plans</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="90"/>
        <source>Use this pose</source>
        <translation>Diese Pose verwenden</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="92"/>
        <source>Make the selected pose the model&apos;s up; the chosen pose&apos;s plan is shown, another pose is searched</source>
        <translation>Die ausgewählte Pose zur Aufwärtsrichtung des Modells machen; für die gewählte Pose wird ihr Plan angezeigt, für eine andere Pose wird gesucht</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="94"/>
        <source>Show current up</source>
        <translation>Aktuelle Aufwärtsrichtung zeigen</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="96"/>
        <source>End the preview of a pose: show the model with its up again</source>
        <translation>Die Vorschau einer Pose beenden: das Modell wieder mit seiner Aufwärtsrichtung zeigen</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="99"/>
        <source>Poses to try:</source>
        <translation>Zu probierende Posen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="100"/>
        <source>Full searches:</source>
        <translation>Volle Suchen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="151"/>
        <location filename="../ui/panels/pose_search_box.cpp" line="159"/>
        <source>Full search of the given up...</source>
        <translation>Volle Suche der vorgegebenen Aufwärtsrichtung...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="161"/>
        <source>Scoring the poses that could beat it with quick plans...</source>
        <translation>Posen, die sie schlagen könnten, werden mit schnellen Plänen bewertet...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="163"/>
        <source>Full searches of the best poses...</source>
        <translation>Volle Suchen für die besten Posen...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="164"/>
        <source>Choosing the best pose...</source>
        <translation>Beste Pose wird gewählt...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="169"/>
        <source>Cancelling the pose search...</source>
        <translation>Posensuche wird abgebrochen...</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="188"/>
        <source>full search</source>
        <translation>volle Suche</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="189"/>
        <source>quick plan</source>
        <translation>schneller Plan</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="190"/>
        <source>ruled out</source>
        <translation>ausgeschlossen</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="191"/>
        <source>not scored</source>
        <translation>nicht bewertet</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="194"/>
        <location filename="../ui/panels/pose_search_box.cpp" line="201"/>
        <source>-</source>
        <translation>-</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="193"/>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="213"/>
        <source>Not searched: at least %1 mm² of this pose&apos;s overhang cannot be saved by any direction the machine prints along, more than the J_G of the given up&apos;s plan, so it could not win</source>
        <translation>Nicht gesucht: mindestens %1 mm² der Überhänge dieser Pose rettet keine Richtung, in der die Maschine druckt, mehr als J_G des Plans der vorgegebenen Aufwärtsrichtung; sie könnte nicht gewinnen</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="218"/>
        <source>chosen</source>
        <translation>gewählt</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/pose_search_box.cpp" line="223"/>
        <source>Best pose: up %1 (%2), J_G %3 mm², %n region(s).</source>
        <translation>
            <numerusform>Beste Pose: Aufwärtsrichtung %1 (%2), J_G %3 mm², %n Bereich.</numerusform>
            <numerusform>Beste Pose: Aufwärtsrichtung %1 (%2), J_G %3 mm², %n Bereiche.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="225"/>
        <source>Cancelled: the poses that finished are listed. %1</source>
        <translation>Abgebrochen: die fertigen Posen sind aufgelistet. %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/pose_search_box.cpp" line="252"/>
        <source>, in use</source>
        <translation>, in Verwendung</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PoseSearchJob</name>
    <message>
        <location filename="../ui/jobs/pose_search_job.cpp" line="83"/>
        <source>Not enough memory for the pose search: lower the beam width, the number of normals or the number of poses.</source>
        <translation>Nicht genug Speicher für die Posensuche: verringern Sie die Strahlbreite, die Zahl der Normalen oder die Zahl der Posen.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/pose_search_job.cpp" line="87"/>
        <location filename="../ui/jobs/pose_search_job.cpp" line="91"/>
        <source>Unexpected error during the pose search.</source>
        <translation>Unerwarteter Fehler während der Posensuche.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/pose_search_job.cpp" line="115"/>
        <source>The pose search was cancelled before any pose finished.</source>
        <translation>Die Posensuche wurde abgebrochen, bevor eine Pose fertig war.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PrintRunDriver</name>
    <message>
        <location filename="../ui/device/print_run_driver.cpp" line="172"/>
        <source>the link to %1 was lost: the run is paused; press Resume once the link is back</source>
        <translation>die Verbindung zu %1 ist abgerissen: der Lauf ist pausiert; drücken Sie „Fortsetzen“, sobald die Verbindung wieder steht</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PrinterLinkOwner</name>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="90"/>
        <source>The printer does not answer yet; MultiDir keeps trying. %1</source>
        <translation>Der Drucker antwortet noch nicht; MultiDir versucht es weiter. %1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="120"/>
        <location filename="../ui/device/printer_link_owner.cpp" line="166"/>
        <source>Printer E-STOP</source>
        <translation>Drucker-NOT-HALT</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="122"/>
        <source>%1 refused: no printer is connected.</source>
        <translation>%1 abgelehnt: kein Drucker verbunden.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="139"/>
        <source>Restart firmware</source>
        <translation>Firmware neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_link_owner.cpp" line="139"/>
        <source>Restart firmware refused: no printer is connected.</source>
        <translation>„Firmware neu starten“ abgelehnt: kein Drucker ist verbunden.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PrinterSection</name>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="45"/>
        <source>%1 °C (off)</source>
        <translation>%1 °C (aus)</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="46"/>
        <source>%1 / %2 °C</source>
        <translation>%1 / %2 °C</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="53"/>
        <location filename="../ui/device/printer_section.cpp" line="294"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="55"/>
        <source>standby (no job)</source>
        <translation>Bereitschaft (kein Auftrag)</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="57"/>
        <source>printing</source>
        <translation>Druck läuft</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="59"/>
        <source>paused</source>
        <translation>pausiert</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="61"/>
        <source>complete</source>
        <translation>abgeschlossen</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="63"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="65"/>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="75"/>
        <source>Printer</source>
        <translation>Drucker</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="79"/>
        <source>http://192.168.0.20:7125</source>
        <translation>http://192.168.0.20:7125</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="80"/>
        <source>The printer&apos;s address: Moonraker (Klipper) as http://HOST:PORT or HOST:PORT (port 7125).</source>
        <translation>Die Adresse des Druckers: Moonraker (Klipper) als http://HOST:PORT oder HOST:PORT (Port 7125).</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="84"/>
        <location filename="../ui/device/printer_section.cpp" line="298"/>
        <location filename="../ui/device/printer_section.cpp" line="312"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="85"/>
        <source>Only when the printer asks for one (Moonraker&apos;s [authorization]). Not remembered.</source>
        <translation>Nur, wenn der Drucker einen verlangt (Moonraker-Abschnitt [authorization]). Wird nicht gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="86"/>
        <source>Connect printer</source>
        <translation>Drucker verbinden</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="87"/>
        <source>Connects to the printer; a print run then sends each region&apos;s G-code to it.</source>
        <translation>Verbindet mit dem Drucker; ein Drucklauf sendet ihm dann den G-Code jedes Bereichs.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="88"/>
        <source>Disconnect printer</source>
        <translation>Drucker trennen</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="89"/>
        <source>Closes the link without commanding the printer: a job on it goes on.</source>
        <translation>Schließt die Verbindung, ohne dem Drucker einen Befehl zu senden: ein Auftrag auf ihm läuft weiter.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="90"/>
        <source>Clear printer E-STOP</source>
        <translation>Drucker-NOT-HALT aufheben</translation>
    </message>
    <message>
        <source>Allows jobs again once the printer confirmed the emergency stop. A Klipper printer also needs FIRMWARE_RESTART on its console.</source>
        <translation type="vanished">Lässt wieder Aufträge zu, sobald der Drucker den Not-Halt bestätigt hat. Ein Klipper-Drucker braucht zusätzlich FIRMWARE_RESTART auf seiner Konsole.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="112"/>
        <source>Address:</source>
        <translation>Adresse:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="113"/>
        <source>API key:</source>
        <translation>API-Schlüssel:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="118"/>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="119"/>
        <source>Job:</source>
        <translation>Auftrag:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="120"/>
        <source>Firmware:</source>
        <translation>Firmware:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="121"/>
        <source>Printer says:</source>
        <translation>Meldung des Druckers:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="122"/>
        <source>Extruder:</source>
        <translation>Extruder:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="123"/>
        <source>Bed:</source>
        <translation>Druckbett:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="124"/>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="125"/>
        <source>Progress:</source>
        <translation>Fortschritt:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="126"/>
        <source>Job time left:</source>
        <translation>Restzeit des Auftrags:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="127"/>
        <source>Last problem:</source>
        <translation>Letztes Problem:</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="154"/>
        <source>Connected to %1.</source>
        <translation>Verbunden mit %1.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="172"/>
        <source>The link to %1 was lost at %2: its values are not the printer&apos;s any more, and it may still be printing. MultiDir keeps trying.</source>
        <translation>Die Verbindung zu %1 ist um %2 abgerissen: die Werte stammen nicht mehr vom Drucker, und er druckt möglicherweise noch. MultiDir versucht es weiter.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="188"/>
        <source>Cannot connect to the printer: %1</source>
        <translation>Keine Verbindung zum Drucker möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="192"/>
        <source>Connecting to %1…</source>
        <translation>Verbindung mit %1 wird hergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="197"/>
        <source>Printer disconnected.</source>
        <translation>Drucker getrennt.</translation>
    </message>
    <message>
        <source>Printer E-STOP cleared. A Klipper printer needs FIRMWARE_RESTART before its next job.</source>
        <translation type="vanished">Drucker-NOT-HALT aufgehoben. Ein Klipper-Drucker braucht vor seinem nächsten Auftrag FIRMWARE_RESTART.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="210"/>
        <source>Clear printer E-STOP refused: %1</source>
        <translation>„Drucker-NOT-HALT aufheben“ abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="251"/>
        <source>step %1 of %2: %3</source>
        <translation>Schritt %1 von %2: %3</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="254"/>
        <source>not started</source>
        <translation>nicht begonnen</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="257"/>
        <source>%1 of %2 (not a step of this run)</source>
        <translation>%1 von %2 (kein Schritt dieses Laufs)</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="263"/>
        <source>none: every step is printed</source>
        <translation>keine: alle Schritte sind gedruckt</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="266"/>
        <source>no estimate: slice the plan before starting the run</source>
        <translation>keine Schätzung: slicen Sie den Plan, bevor Sie den Lauf starten</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="268"/>
        <source>%1 of printing (done about %2; platform moves not counted)</source>
        <translation>%1 Druckzeit (fertig gegen %2; Plattformbewegungen nicht mitgerechnet)</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="279"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="281"/>
        <source>Not reachable; MultiDir keeps trying…</source>
        <translation>Nicht erreichbar; MultiDir versucht es weiter…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="283"/>
        <source>Connecting…</source>
        <translation>Verbindung wird hergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="285"/>
        <source>Link lost at %1; MultiDir keeps trying…</source>
        <translation>Verbindung um %1 abgerissen; MultiDir versucht es weiter…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="287"/>
        <source>Connected to %1</source>
        <translation>Verbunden mit %1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="295"/>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="340"/>
        <source>%1 does not answer: %2</source>
        <translation>%1 antwortet nicht: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="342"/>
        <source>The printer&apos;s firmware is %1: %2</source>
        <translation>Die Firmware des Druckers ist im Zustand %1: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="344"/>
        <source>it says nothing more</source>
        <translation>weitere Angaben macht sie nicht</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="346"/>
        <source>The print run is paused: %1.</source>
        <translation>Der Drucklauf ist pausiert: %1.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="91"/>
        <source>Allows jobs again once the printer confirmed the emergency stop. A printer whose firmware the stop shut down also needs Restart firmware.</source>
        <translation>Erlaubt wieder Aufträge, sobald der Drucker den NOT-HALT bestätigt hat. Ein Drucker, dessen Firmware der NOT-HALT abgeschaltet hat, braucht außerdem „Firmware neu starten“.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="94"/>
        <source>Restart firmware</source>
        <translation>Firmware neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="95"/>
        <source>After an emergency stop: Klipper&apos;s FIRMWARE_RESTART (through Moonraker), or OctoPrint connecting to the printer again (which resets its board). Asks first.</source>
        <translation>Nach einem NOT-HALT: FIRMWARE_RESTART von Klipper (über Moonraker), oder OctoPrint verbindet sich erneut mit dem Drucker (was seine Platine zurücksetzt). Fragt zuerst.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="203"/>
        <source>Printer E-STOP cleared.</source>
        <translation>Drucker-NOT-HALT aufgehoben.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="205"/>
        <source>Printer E-STOP cleared. Its firmware is %1: it needs Restart firmware (Klipper&apos;s FIRMWARE_RESTART) before its next job.</source>
        <translation>Drucker-NOT-HALT aufgehoben. Seine Firmware ist im Zustand %1: sie braucht „Firmware neu starten“ (FIRMWARE_RESTART von Klipper) vor dem nächsten Auftrag.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="145"/>
        <source>%1 is restarting its firmware; the Firmware line shows &quot;ready&quot; once it is back.</source>
        <translation>%1 startet seine Firmware neu; die Zeile „Firmware“ zeigt „ready“, sobald sie wieder läuft.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="149"/>
        <source>Restart firmware refused: %1</source>
        <translation>„Firmware neu starten“ abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="214"/>
        <source>Restart Printer Firmware</source>
        <translation>Drucker-Firmware neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="215"/>
        <source>Restart the firmware of %1?</source>
        <translation>Die Firmware von %1 neu starten?</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="218"/>
        <source>The firmware takes the heaters and motors back: make sure whatever caused the emergency stop is fixed and nothing is in the printer&apos;s way.</source>
        <translation>Die Firmware übernimmt wieder Heizungen und Motoren: stellen Sie sicher, dass die Ursache des NOT-HALTs behoben ist und dem Drucker nichts im Weg ist.</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="220"/>
        <source>&amp;Restart Firmware</source>
        <translation>Firmware &amp;neu starten</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="228"/>
        <source>Restarting the firmware of %1…</source>
        <translation>Die Firmware von %1 wird neu gestartet…</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="308"/>
        <source>unknown since %1: the printer&apos;s link is lost</source>
        <translation>unbekannt seit %1: die Verbindung zum Drucker ist verloren</translation>
    </message>
    <message>
        <location filename="../ui/device/printer_section.cpp" line="325"/>
        <source>%1&apos;s firmware is ready again.</source>
        <translation>Die Firmware von %1 ist wieder bereit.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ProjectSession</name>
    <message>
        <location filename="../ui/project/project_session.cpp" line="87"/>
        <source>Open &amp;Project...</source>
        <translation>Pr&amp;ojekt öffnen...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="89"/>
        <source>Open a MultiDir project (.multidir): its model, settings and plan</source>
        <translation>Ein MultiDir-Projekt (.multidir) öffnen: sein Modell, seine Einstellungen und seinen Plan</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="93"/>
        <source>&amp;Save Project</source>
        <translation>Pro&amp;jekt speichern</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="96"/>
        <source>Save the model reference, the settings and the plan in a project file</source>
        <translation>Modellverweis, Einstellungen und Plan in einer Projektdatei speichern</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="97"/>
        <source>Save Project &amp;As...</source>
        <translation>Projekt speichern &amp;unter...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="108"/>
        <source>There is no model to save a project for: open a model first.</source>
        <translation>Es gibt kein Modell, für das ein Projekt gespeichert werden könnte: öffnen Sie zuerst ein Modell.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="117"/>
        <source>The model shown has no file (it is the regions of a plan opened without its model): open the model itself to save a project.</source>
        <translation>Das angezeigte Modell hat keine Datei (es besteht aus den Bereichen eines ohne sein Modell geöffneten Plans): öffnen Sie das Modell selbst, um ein Projekt zu speichern.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="137"/>
        <source>Wait until the project has opened before saving.</source>
        <translation>Warten Sie mit dem Speichern, bis das Projekt geöffnet ist.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="140"/>
        <source>Cannot save the project: %1</source>
        <translation>Das Projekt kann nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="143"/>
        <source>Could not save the project %1: %2 (%3)</source>
        <translation>Das Projekt %1 konnte nicht gespeichert werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="150"/>
        <source>Project saved to %1.</source>
        <translation>Projekt unter %1 gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="162"/>
        <location filename="../ui/project/project_session.cpp" line="176"/>
        <location filename="../ui/project/project_session.cpp" line="181"/>
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="176"/>
        <source>MultiDir projects (*.multidir)</source>
        <translation>MultiDir-Projekte (*.multidir)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="186"/>
        <location filename="../ui/project/project_session.cpp" line="579"/>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="187"/>
        <source>MultiDir projects (*.multidir);;All files (*)</source>
        <translation>MultiDir-Projekte (*.multidir);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="221"/>
        <source>Search Running</source>
        <translation>Suche läuft</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="222"/>
        <source>A search is running on %1.</source>
        <translation>Für %1 läuft gerade eine Suche.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="223"/>
        <source>the model shown</source>
        <translation>das angezeigte Modell</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="226"/>
        <source>Stop it? Its result is then dropped.</source>
        <translation>Anhalten? Ihr Ergebnis wird dann verworfen.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="227"/>
        <source>S&amp;top the Search</source>
        <translation>Suche an&amp;halten</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="251"/>
        <source>%1 is no longer there; it was taken off the recent files.</source>
        <translation>%1 ist nicht mehr vorhanden und wurde aus der Liste der zuletzt geöffneten Dateien entfernt.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="271"/>
        <source>Cannot open %1: drop a mesh file (.stl, .obj, .off, .ply) or a MultiDir project (.multidir).</source>
        <translation>%1 kann nicht geöffnet werden: ziehen Sie eine Netzdatei (.stl, .obj, .off, .ply) oder ein MultiDir-Projekt (.multidir) hierher.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="284"/>
        <source>There is no autosaved project to recover.</source>
        <translation>Es gibt kein automatisch gespeichertes Projekt zum Wiederherstellen.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="294"/>
        <source>Recover Unsaved Work</source>
        <translation>Nicht gespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="295"/>
        <source>MultiDir Studio did not close properly. Recover the project it autosaved on %1?</source>
        <translation>MultiDir Studio wurde nicht ordnungsgemäß beendet. Das am %1 automatisch gespeicherte Projekt wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="300"/>
        <source>It was an untitled project.</source>
        <translation>Es war ein unbenanntes Projekt.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="301"/>
        <source>It holds unsaved changes to %1.</source>
        <translation>Es enthält nicht gespeicherte Änderungen an %1.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="302"/>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="303"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="304"/>
        <source>&amp;Later</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="348"/>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="349"/>
        <source>Unsaved Changes</source>
        <translation>Nicht gespeicherte Änderungen</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="350"/>
        <source>The project %1 has changes that are not saved.</source>
        <translation>Das Projekt %1 enthält Änderungen, die nicht gespeichert sind.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="353"/>
        <source>Save them first?</source>
        <translation>Zuerst speichern?</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="450"/>
        <location filename="../ui/project/project_session.cpp" line="488"/>
        <source>Opening %1 was interrupted: another model was opened.</source>
        <translation>Das Öffnen von %1 wurde unterbrochen: ein anderes Modell wurde geöffnet.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="468"/>
        <source>Rebuilding the plan of %1...</source>
        <translation>Plan von %1 wird neu aufgebaut...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="495"/>
        <source>The model file %1 changed since the project was saved; the plan was recomputed on the changed file.</source>
        <translation>Die Modelldatei %1 hat sich seit dem Speichern des Projekts geändert; der Plan wurde für die geänderte Datei neu berechnet.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="509"/>
        <source>The rebuilt plan leaves %1 mm² of risky area; the project saved %2 mm².</source>
        <translation>Der neu aufgebaute Plan lässt %1 mm² Risikofläche übrig; im Projekt gespeichert waren %2 mm².</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="514"/>
        <source>The plan could not be rebuilt on this model (%1); the model is shown without it.</source>
        <translation>Der Plan konnte für dieses Modell nicht neu aufgebaut werden (%1); das Modell wird ohne ihn angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="530"/>
        <source>Recovered the autosaved project.</source>
        <translation>Das automatisch gespeicherte Projekt wurde wiederhergestellt.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="531"/>
        <source>Project %1 opened.</source>
        <translation>Projekt %1 geöffnet.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="534"/>
        <source>Project %1</source>
        <translation>Projekt %1</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="544"/>
        <source>Could not open the project %1: %2</source>
        <translation>Das Projekt %1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="559"/>
        <source>Could not open the project %1: its model %2 is missing.</source>
        <translation>Das Projekt %1 konnte nicht geöffnet werden: sein Modell %2 fehlt.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="560"/>
        <source>Put the model back at %1, or open the model where it is now and save the project again.</source>
        <translation>Legen Sie das Modell wieder unter %1 ab, oder öffnen Sie das Modell an seinem jetzigen Ort und speichern Sie das Projekt erneut.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="565"/>
        <source>Opening the project %1...</source>
        <translation>Projekt %1 wird geöffnet...</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="578"/>
        <source>%1 is still open.</source>
        <translation>%1 ist weiterhin geöffnet.</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="608"/>
        <source>MultiDir Studio[*]</source>
        <translation>MultiDir Studio[*]</translation>
    </message>
    <message>
        <location filename="../ui/project/project_session.cpp" line="608"/>
        <source>%1[*] - MultiDir Studio</source>
        <translation>%1[*] - MultiDir Studio</translation>
    </message>
</context>
<context>
    <name>multidir::ui::RecentFilesMenu</name>
    <message>
        <location filename="../ui/project/recent_files.cpp" line="41"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../ui/project/recent_files.cpp" line="68"/>
        <source>&amp;Clear Recent</source>
        <translation>Liste &amp;leeren</translation>
    </message>
</context>
<context>
    <name>multidir::ui::RobotCellSection</name>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="63"/>
        <source>Robot cell (Universal Robots)</source>
        <translation>Roboterzelle (Universal Robots)</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="70"/>
        <source>host or host:port (the dashboard&apos;s port; UR&apos;s own 29999 when left out)</source>
        <translation>Host oder Host:Port (der Port des Dashboards; ohne Angabe UR-eigener Port 29999)</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="73"/>
        <source>the folder &apos;multidir robot-program&apos; wrote</source>
        <translation>der Ordner, den „multidir robot-program“ geschrieben hat</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="74"/>
        <source>Open job folder…</source>
        <translation>Auftragsordner öffnen…</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="75"/>
        <source>Convert the sliced job</source>
        <translation>Geslicten Auftrag umwandeln</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="77"/>
        <source>The plan&apos;s sliced job turned into the cell&apos;s programs (as multidir robot-program does), for the cell on the Machine tab</source>
        <translation>Der geslicte Auftrag des Plans als Programme der Zelle (wie multidir robot-program), für die Zelle im Reiter Maschine</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="79"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="84"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="85"/>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="91"/>
        <source>Start job</source>
        <translation>Auftrag starten</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="92"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="93"/>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="94"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="95"/>
        <location filename="../ui/device/robot_cell_section.cpp" line="503"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="115"/>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="117"/>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="118"/>
        <source>Joints:</source>
        <translation>Gelenke:</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="119"/>
        <source>Robot job:</source>
        <translation>Roboterauftrag:</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="121"/>
        <source>Step:</source>
        <translation>Schritt:</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="134"/>
        <source>Conversion cancelled.</source>
        <translation>Umwandlung abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="148"/>
        <source>%1 of %2: %3 sent</source>
        <translation>%1 von %2: %3 gesendet</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="153"/>
        <source>movel %1 of %2</source>
        <translation>movel %1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="153"/>
        <source>between movels (a joint move)</source>
        <translation>zwischen movel-Befehlen (eine Gelenkbewegung)</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="154"/>
        <source>%1 of %2: %3, %4 %, about %5 left</source>
        <translation>%1 von %2: %3, %4 %, noch etwa %5</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="162"/>
        <source>The robot reports: %1</source>
        <translation>Der Roboter meldet: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="165"/>
        <source>Cannot pause: %1. Stop ends the run.</source>
        <translation>Pause nicht möglich: %1. Stopp beendet den Lauf.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="167"/>
        <source>paused after movel %1 of %2; the extruder stopped, the platform %3 mm off the nozzle</source>
        <translation>pausiert nach movel %1 von %2; Extruder gestoppt, Plattform %3 mm von der Düse entfernt</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="172"/>
        <source>%1 of %2: %3</source>
        <translation>%1 von %2: %3</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="173"/>
        <source>Paused at a safe point. Resume goes on from there; Stop ends the run.</source>
        <translation>An einem sicheren Punkt pausiert. Fortsetzen macht dort weiter; Stopp beendet den Lauf.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="178"/>
        <source>Resuming step %1 after movel %2: back down to the nozzle, then the rest of the step.</source>
        <translation>Schritt %1 wird nach movel %2 fortgesetzt: zurück an die Düse, dann der Rest des Schritts.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="186"/>
        <source>%1 of %2 done in %3 of the robot&apos;s time</source>
        <translation>%1 von %2 fertig in %3 Roboterzeit</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="217"/>
        <source>The link to the robot at %1 is lost (%2). The robot&apos;s values are unknown; MultiDir keeps trying to reconnect and sends a latched stop first thing once it is back.</source>
        <translation>Die Verbindung zum Roboter unter %1 ist unterbrochen (%2). Die Werte des Roboters sind unbekannt; MultiDir versucht weiter, sich neu zu verbinden, und sendet einen gehaltenen Stopp als Erstes, sobald sie wieder besteht.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="220"/>
        <source>The robot job run is ending: it stops the program.</source>
        <translation>Der Roboterauftrag endet: er stoppt das Programm.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="226"/>
        <source>Open a robot job folder (multidir robot-program OUT)</source>
        <translation>Roboterauftragsordner öffnen (multidir robot-program OUT)</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="233"/>
        <source>There is no robot cell: choose the machine &quot;robot arm under a fixed extruder&quot;.</source>
        <translation>Es gibt keine Roboterzelle: wählen Sie die Maschine „Roboterarm unter festem Extruder“.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="238"/>
        <source>The plan shown is not sliced: slice it with the cell&apos;s profile (ur5-cell-0.8) first.</source>
        <translation>Der angezeigte Plan ist nicht geslict: slicen Sie ihn zuerst mit dem Profil der Zelle (ur5-cell-0.8).</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="243"/>
        <source>No folder for the converted job: %1</source>
        <translation>Kein Ordner für den umgewandelten Auftrag: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="275"/>
        <source>The sliced job cannot be converted for the cell: %1</source>
        <translation>Der geslicte Auftrag lässt sich nicht für die Zelle umwandeln: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="280"/>
        <source>Converted for the cell: %1 steps in %2.</source>
        <translation>Für die Zelle umgewandelt: %1 Schritte in %2.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="288"/>
        <source>Converting the sliced job for the cell…</source>
        <translation>Geslicter Auftrag wird für die Zelle umgewandelt…</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="299"/>
        <source>The robot&apos;s address: %1</source>
        <translation>Adresse des Roboters: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="309"/>
        <source>Connecting to the robot at %1…</source>
        <translation>Verbindung zum Roboter unter %1…</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="327"/>
        <source>The robot at %1 cannot be reached: %2</source>
        <translation>Der Roboter unter %1 ist nicht erreichbar: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="331"/>
        <source>Connected to the robot at %1.</source>
        <translation>Mit dem Roboter unter %1 verbunden.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="340"/>
        <source>A robot job run is under way: Stop it before disconnecting.</source>
        <translation>Ein Roboterauftrag läuft: stoppen Sie ihn vor dem Trennen.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="354"/>
        <source>Start refused: %1</source>
        <translation>Start abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="358"/>
        <source>no robot is connected: Connect first.</source>
        <translation>kein Roboter verbunden: zuerst verbinden.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="366"/>
        <source>the document has no robot cell: set the cell on the Machine tab (the job was made for %1).</source>
        <translation>das Dokument hat keine Roboterzelle: legen Sie die Zelle im Reiter Maschine fest (der Auftrag wurde für %1 erstellt).</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="371"/>
        <source>the job&apos;s cell (%1) cannot be read: %2</source>
        <translation>die Zelle des Auftrags (%1) ist nicht lesbar: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="374"/>
        <source>the job&apos;s cell (%1) is not the cell on the Machine tab: convert the job again with this cell, or load the job&apos;s cell on the Machine tab.</source>
        <translation>die Zelle des Auftrags (%1) ist nicht die Zelle im Reiter Maschine: wandeln Sie den Auftrag mit dieser Zelle neu um oder laden Sie die Zelle des Auftrags im Reiter Maschine.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="379"/>
        <source>no plan is shown: open the plan the job was made from.</source>
        <translation>kein Plan angezeigt: öffnen Sie den Plan, aus dem der Auftrag erstellt wurde.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="382"/>
        <source>the job was converted from another plan than the one shown: convert the sliced job again.</source>
        <translation>der Auftrag wurde aus einem anderen als dem angezeigten Plan umgewandelt: wandeln Sie den geslicten Auftrag neu um.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="384"/>
        <source>the job has %1 steps but the plan shown has %2 regions: it was made from another plan.</source>
        <translation>der Auftrag hat %1 Schritte, der angezeigte Plan aber %2 Bereiche: er wurde aus einem anderen Plan erstellt.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="391"/>
        <source>the robot has not confirmed its stop yet (%1).</source>
        <translation>der Roboter hat seinen Stopp noch nicht bestätigt (%1).</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="409"/>
        <source>starting: %1 steps</source>
        <translation>Start: %1 Schritte</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="410"/>
        <source>Robot job started: %1 steps.</source>
        <translation>Roboterauftrag gestartet: %1 Schritte.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="418"/>
        <source>Pause asked for: the arm finishes the move under way, the extruder stops and the platform backs off the nozzle.</source>
        <translation>Pause angefordert: der Arm beendet die laufende Bewegung, der Extruder stoppt und die Plattform entfernt sich von der Düse.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="448"/>
        <source>E-STOP sent to the robot (stop, then power off). To go on: release it on the teach pendant if pressed there; Start powers the arm on again once the robot confirmed the stop.</source>
        <translation>NOT-HALT an den Roboter gesendet (Stopp, dann Ausschalten). Zum Weitermachen: am Handbediengerät lösen, falls dort gedrückt; Start schaltet den Arm wieder ein, sobald der Roboter den Stopp bestätigt hat.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="460"/>
        <source>done: %1 steps printed</source>
        <translation>fertig: %1 Schritte gedruckt</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="461"/>
        <source>The robot job is done: %1 steps printed.</source>
        <translation>Der Roboterauftrag ist fertig: %1 Schritte gedruckt.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="465"/>
        <source>The robot did not start the job: %1</source>
        <translation>Der Roboter hat den Auftrag nicht gestartet: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="469"/>
        <source>stopped in step %1 of %2</source>
        <translation>gestoppt in Schritt %1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="470"/>
        <source>The run stopped in step %1: %2</source>
        <translation>Der Lauf wurde in Schritt %1 gestoppt: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="487"/>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="488"/>
        <location filename="../ui/device/robot_cell_section.cpp" line="493"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="492"/>
        <source>unknown: the link is lost (%1)</source>
        <translation>unbekannt: die Verbindung ist unterbrochen (%1)</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="495"/>
        <source>robot mode %1, safety mode %2, program %3</source>
        <translation>Robotermodus %1, Sicherheitsmodus %2, Programm %3</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="500"/>
        <source>%1 deg</source>
        <translation>%1 Grad</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="503"/>
        <source>stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="504"/>
        <source>Robot: %1 confirmed by the robot.</source>
        <translation>Roboter: %1 vom Roboter bestätigt.</translation>
    </message>
    <message>
        <location filename="../ui/device/robot_cell_section.cpp" line="505"/>
        <source>Robot: %1 not confirmed yet (%2); MultiDir keeps resending it.</source>
        <translation>Roboter: %1 noch nicht bestätigt (%2); MultiDir sendet ihn weiter.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SearchJob</name>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="26"/>
        <source>The search was cancelled while growing supports: the plan is shown without them.</source>
        <translation>Die Suche wurde beim Erzeugen der Stützen abgebrochen: der Plan wird ohne sie angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="28"/>
        <source>The supports could not be grown: %1 (%2)</source>
        <translation>Die Stützen konnten nicht erzeugt werden: %1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="32"/>
        <source>Not enough memory to grow the supports: the plan is shown without them.</source>
        <translation>Nicht genug Speicher, um die Stützen zu erzeugen: der Plan wird ohne sie angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="34"/>
        <source>Unexpected error while growing the supports: %1</source>
        <translation>Unerwarteter Fehler beim Erzeugen der Stützen: %1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/support_growth.cpp" line="36"/>
        <source>Unexpected error while growing the supports.</source>
        <translation>Unerwarteter Fehler beim Erzeugen der Stützen.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="96"/>
        <source>growing supports</source>
        <translation>Stützen werden erzeugt</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="107"/>
        <source>Not enough memory for this search: lower the beam width or the number of normals.</source>
        <translation>Nicht genug Speicher für diese Suche: verringern Sie die Strahlbreite oder die Zahl der Normalen.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="110"/>
        <location filename="../ui/jobs/search_job.cpp" line="114"/>
        <source>Unexpected error during the search.</source>
        <translation>Unerwarteter Fehler während der Suche.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SearchPanel</name>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="46"/>
        <source>Beam search (Algorithm 1)</source>
        <translation>Strahlsuche (Algorithmus 1)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="47"/>
        <source>Constrained greedy</source>
        <translation>Eingeschränkt gierig</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="48"/>
        <source>Greedy</source>
        <translation>Gierig</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="53"/>
        <source>How many partial plans each level keeps (b)</source>
        <translation>Wie viele Teilpläne jede Ebene behält (b)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="59"/>
        <source>w: every region cut off keeps at least the model&apos;s volume divided by w</source>
        <translation>w: jeder abgetrennte Bereich behält mindestens das Modellvolumen geteilt durch w</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="64"/>
        <source>Beam search only: runs at this many region scales side by side, the smallest region V/w, V/2w, V/4w, ..., the beam width shared among them, and keeps the best plan. No single w suits every model. 1: one beam search at w</source>
        <translation>Nur Strahlsuche: läuft nebeneinander auf so vielen Regionsskalen (kleinste Region V/w, V/2w, V/4w, ...), teilt die Strahlbreite unter ihnen auf und behält den besten Plan. Kein einzelnes w passt zu jedem Modell. 1: eine Strahlsuche bei w</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="71"/>
        <source>Candidate normals sampled on the whole sphere (5-DOF)</source>
        <translation>Kandidatennormalen, auf der ganzen Kugel abgetastet (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="76"/>
        <location filename="../ui/panels/search_panel.cpp" line="90"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="78"/>
        <source>Distance between candidate planes along each normal</source>
        <translation>Abstand der Kandidatenebenen entlang jeder Normalen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="83"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="85"/>
        <source>Maximal self-supporting angle the search plans for</source>
        <translation>Größter selbsttragender Winkel, mit dem die Suche plant</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="92"/>
        <source>No region, the one on the platform included, is thinner than this along its printing direction</source>
        <translation>Kein Bereich, auch nicht der auf der Plattform, ist entlang seiner Druckrichtung dünner als dieser Wert</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="98"/>
        <source> % of J_G</source>
        <translation> % von J_G</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="100"/>
        <source>A plane stays only if removing it would raise J_G by at least this share of J_G before (and by at least 1 mm²): each region costs a platform move and a seam</source>
        <translation>Eine Ebene bleibt nur, wenn ihr Entfernen J_G um mindestens diesen Anteil des vorherigen J_G (und um mindestens 1 mm²) erhöhen würde: jeder Bereich kostet eine Plattformbewegung und eine Naht</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="123"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="124"/>
        <source>After the search, move every plane continuously (normal and offset) to lower J_G further, every constraint kept; higher values refine more finely and take longer</source>
        <translation>Nach der Suche jede Ebene stufenlos verschieben (Normale und Versatz), um J_G weiter zu senken, wobei alle Bedingungen eingehalten werden; höhere Werte verfeinern genauer und dauern länger</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="140"/>
        <source>machine&apos;s axis only</source>
        <translation>nur Achse der Maschine</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="141"/>
        <source>4-DOF: also try this many rotation axes spread over 180° and keep the best</source>
        <translation>4-DOF: zusätzlich so viele über 180° verteilte Drehachsen probieren und die beste behalten</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="144"/>
        <source>Scheme:</source>
        <translation>Verfahren:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="145"/>
        <source>Beam width:</source>
        <translation>Strahlbreite:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="147"/>
        <source>Volume divisor w:</source>
        <translation>Volumenteiler w:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="148"/>
        <source>Scales:</source>
        <translation>Skalen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="150"/>
        <source>Normals:</source>
        <translation>Normalen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="151"/>
        <source>Offset step:</source>
        <translation>Versatzschritt:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="152"/>
        <source>Max. overhang angle α:</source>
        <translation>Max. Überhangwinkel α:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="153"/>
        <source>Min. region height:</source>
        <translation>Min. Bereichshöhe:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="154"/>
        <source>Min. gain per plane:</source>
        <translation>Min. Gewinn je Ebene:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="159"/>
        <source>Polish the planes:</source>
        <translation>Ebenen polieren:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="126"/>
        <source>also the finalists</source>
        <translation>auch die Finalisten</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="129"/>
        <source>Also polish the search&apos;s best plan for every other number of cuts that may beat its own plan, and keep the least J_G: the plan changes less with the settings</source>
        <translation>Auch den besten Plan der Suche für jede andere Zahl von Schnitten polieren, der ihren eigenen Plan schlagen kann, und den mit dem kleinsten J_G behalten: der Plan ändert sich weniger mit den Einstellungen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="131"/>
        <source>the tails of the polished plan</source>
        <translation>die hinteren Ebenen des polierten Plans</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="134"/>
        <source>After polishing, search the plan&apos;s later planes again from each of its polished states and keep a lower plan found there: lower J_G on some models, about twice the time</source>
        <translation>Nach dem Polieren die späteren Ebenen des Plans von jedem seiner polierten Zustände aus neu suchen und einen dort gefundenen niedrigeren Plan behalten: bei manchen Modellen kleineres J_G, etwa doppelte Zeit</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="160"/>
        <source>Search again:</source>
        <translation>Erneut suchen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="161"/>
        <source>Axes to try:</source>
        <translation>Zu probierende Achsen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="168"/>
        <source>&amp;Run search</source>
        <translation>Suche &amp;starten</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="171"/>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="202"/>
        <source>Progress</source>
        <translation>Fortschritt</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="210"/>
        <source>Level:</source>
        <translation>Stufe:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="211"/>
        <source>Beams alive:</source>
        <translation>Aktive Strahlen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="212"/>
        <source>Best J_G:</source>
        <translation>Bestes J_G:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="213"/>
        <source>Candidates scored:</source>
        <translation>Bewertete Kandidaten:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="235"/>
        <source>Open a model first.</source>
        <translation>Öffnen Sie zuerst ein Modell.</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="301"/>
        <source>Search for clipping planes that make the model printable with less support</source>
        <translation>Nach Schnittebenen suchen, mit denen das Modell mit weniger Stützen druckbar wird</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="367"/>
        <source>%1 (polishing)</source>
        <translation>%1 (Polieren)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="382"/>
        <source>Cancelling: keeping the best plan so far... %1</source>
        <translation>Abbruch: der bisher beste Plan wird behalten... %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="384"/>
        <source>%1 %2 - %3</source>
        <translation>%1 %2 - %3</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="386"/>
        <source>Level 1 of %1: scoring candidates... %2</source>
        <translation>Stufe 1 von %1: Kandidaten werden bewertet... %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="387"/>
        <source>Scoring candidates... %1</source>
        <translation>Kandidaten werden bewertet... %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="391"/>
        <source>Polishing the planes: %1 % · best J_G %2 mm² · %3</source>
        <translation>Ebenen polieren: %1 % · bestes J_G %2 mm² · %3</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="396"/>
        <source>Level %1 of %2</source>
        <translation>Stufe %1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="396"/>
        <source>Level %1</source>
        <translation>Ebene %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="397"/>
        <source>Axis %1 of %2, %3</source>
        <translation>Achse %1 von %2, %3</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="400"/>
        <source>%1 · beams alive: %2 · best J_G %3 mm² · %4 candidates · %5</source>
        <translation>%1 · aktive Strahlen: %2 · bestes J_G %3 mm² · %4 Kandidaten · %5</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="439"/>
        <source>The search ran on a simplified copy of %1 faces; its planes then cut the full model, and every number shown is the full model&apos;s.</source>
        <translation>Die Suche lief auf einer vereinfachten Kopie mit %1 Flächen; ihre Ebenen schneiden danach das vollständige Modell, und alle angezeigten Zahlen beziehen sich auf das vollständige Modell.</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="462"/>
        <source>Stopped</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="340"/>
        <location filename="../ui/panels/search_panel.cpp" line="369"/>
        <location filename="../ui/panels/search_panel.cpp" line="418"/>
        <source>%1 mm²</source>
        <translation>%1 mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="365"/>
        <source>%1 (axis %2 of %3)</source>
        <translation>%1 (Achse %2 von %3)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="417"/>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="417"/>
        <source>Done</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="423"/>
        <source>Cancelled: showing the best plan found so far.</source>
        <translation>Abgebrochen: der bisher beste Plan wird angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="427"/>
        <source>Nothing improved: no clipping plane lowers the risky area (J_G stays %1 mm²). Try more normals, a smaller offset step, a larger w or another machine.</source>
        <translation>Keine Verbesserung: keine Schnittebene verringert die Risikofläche (J_G bleibt %1 mm²). Versuchen Sie mehr Normalen, einen kleineren Versatzschritt, ein größeres w oder eine andere Maschine.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/search_panel.cpp" line="432"/>
        <source>Not support-free: %1 mm² still needs support (was %2 mm²), in %n region(s).</source>
        <translation>
            <numerusform>Nicht stützenfrei: %1 mm² brauchen noch Stützen (vorher %2 mm²), in %n Bereich.</numerusform>
            <numerusform>Nicht stützenfrei: %1 mm² brauchen noch Stützen (vorher %2 mm²), in %n Bereichen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/search_panel.cpp" line="436"/>
        <source>Support-free in %n region(s) (J_G was %1 mm²).</source>
        <translation>
            <numerusform>Stützenfrei in %n Bereich (J_G war %1 mm²).</numerusform>
            <numerusform>Stützenfrei in %n Bereichen (J_G war %1 mm²).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="454"/>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="455"/>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="106"/>
        <source> mm²</source>
        <translation> mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="108"/>
        <source>Apart: the risky area one more part must save, for its dowels and handling (the support whose print time equals its dowels&apos;)</source>
        <translation>Getrennt: die Risikofläche, die ein weiteres Teil einsparen muss, für seine Dübel und die Handhabung (die Stützen, deren Druckzeit der seiner Dübel gleicht)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="114"/>
        <source> mm² per mm² of cut face</source>
        <translation> mm² je mm² Schnittfläche</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="116"/>
        <source>Apart: the risky area one more part must save for every mm² of its cut face, whose two sides are printed solid</source>
        <translation>Getrennt: die Risikofläche, die ein weiteres Teil je mm² seiner Schnittfläche einsparen muss, deren beide Seiten massiv gedruckt werden</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="163"/>
        <source>Price of a part:</source>
        <translation>Preis eines Teils:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="165"/>
        <source>... and of its cut face:</source>
        <translation>... und seiner Schnittfläche:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="399"/>
        <source>Apart search (1 of 2), %1</source>
        <translation>Suche für den getrennten Druck (1 von 2), %1</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="399"/>
        <source>5-DOF search for the bound (2 of 2), %1</source>
        <translation>5-DOF-Suche für die Schranke (2 von 2), %1</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SliceDialog</name>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="82"/>
        <source>The firmware turns the platform (axis %1): one program, job.gcode, with every step.</source>
        <translation>Die Firmware dreht die Plattform (Achse %1): ein Programm, job.gcode, mit allen Schritten.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="85"/>
        <source>MultiDir turns the platform over Modbus (Hardware dock): one program per step.</source>
        <translation>MultiDir dreht die Plattform über Modbus (Fenster „Hardware“): ein Programm je Schritt.</translation>
    </message>
    <message>
        <source>The firmware tilts (axis %1) and rotates (axis %2) the platform; MultiDir does not write their program yet, so it prints one-step plans only.</source>
        <translation type="vanished">Die Firmware kippt (Achse %1) und dreht (Achse %2) die Plattform; MultiDir schreibt deren Programm noch nicht, daher druckt sie nur Pläne mit einem Schritt.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="27"/>
        <source>Klipper with tilt and rotation steppers, 0.4 mm nozzle</source>
        <translation>Klipper mit Kipp- und Drehschrittmotor, 0,4-mm-Düse</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="28"/>
        <source>Klipper with a rotary A axis, 0.4 mm nozzle</source>
        <translation>Klipper mit einer Drehachse A, 0,4-mm-Düse</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="29"/>
        <source>Generic Marlin 220x220, 0.4 mm nozzle (platform over Modbus)</source>
        <translation>Generischer Marlin 220x220, 0,4-mm-Düse (Plattform über Modbus)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="30"/>
        <source>Open5x-like Prusa i3, RepRapFirmware U tilt + V rotation, 0.4 mm nozzle</source>
        <translation>Prusa i3 nach Art von Open5x, RepRapFirmware U kippen + V drehen, 0,4-mm-Düse</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="32"/>
        <source>Robot arm tilting the platform, printer head moving, 0.8 mm nozzle</source>
        <translation>Roboterarm neigt die Plattform, Druckkopf bewegt sich, 0,8-mm-Düse</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="33"/>
        <source>UR5 robot cell, fixed 0.8 mm extruder</source>
        <translation>UR5-Roboterzelle, feststehender 0,8-mm-Extruder</translation>
    </message>
    <message>
        <source>A plan printed apart is sliced part by part on plates: use &apos;multidir apart&apos; (docs/apart.md).</source>
        <translation type="vanished">Ein getrennt gedruckter Plan wird Teil für Teil auf Druckplatten gesliced: verwenden Sie „multidir apart“ (docs/apart.md).</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="65"/>
        <source>This printer cannot turn the part: it prints one-step (3-DOF) plans only.</source>
        <translation>Dieser Drucker kann das Teil nicht drehen: er druckt nur einstufige (3-DOF) Pläne.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="69"/>
        <source>This printer turns the platform about one axis: it cannot print a 5-DOF plan. Choose a printer with two firmware axes or a robot arm.</source>
        <translation>Dieser Drucker dreht die Plattform nur um eine Achse: er kann keinen 5-DOF-Plan drucken. Wählen Sie einen Drucker mit zwei Firmware-Achsen oder einen Roboterarm.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="87"/>
        <source>The firmware tilts (axis %1) and rotates (axis %2) the platform: one program, job.gcode, with every step and the turns between them.</source>
        <translation>Die Firmware kippt (Achse %1) und dreht (Achse %2) die Plattform: ein Programm, job.gcode, mit allen Schritten und den Drehungen dazwischen.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="93"/>
        <source>An ordinary printer: it cannot turn the part, so it prints one-step plans only.</source>
        <translation>Ein gewöhnlicher Drucker: er kann das Teil nicht drehen und druckt daher nur Pläne mit einem Schritt.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="100"/>
        <source>Slice the Plan</source>
        <translation>Plan slicen</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="115"/>
        <source>Load a PrusaSlicer .ini...</source>
        <translation>PrusaSlicer-.ini laden...</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="125"/>
        <source>How the firmware turns the platform: Klipper&apos;s MANUAL_STEPPER, or G1 A on Marlin and RepRapFirmware</source>
        <translation>Wie die Firmware die Plattform dreht: MANUAL_STEPPER bei Klipper oder G1 A bei Marlin und RepRapFirmware</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="130"/>
        <source>layer_height=0.3 fill_density=10%</source>
        <translation>layer_height=0.3 fill_density=10%</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="131"/>
        <source>PrusaSlicer settings over the profile&apos;s, KEY=VALUE separated by spaces</source>
        <translation>PrusaSlicer-Einstellungen, die die des Profils überschreiben, als KEY=VALUE durch Leerzeichen getrennt</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="132"/>
        <source>Also slice the whole model along up with the slicer&apos;s supports (comparison)</source>
        <translation>Zusätzlich das ganze Modell in Aufwärtsrichtung mit den Stützen des Slicers slicen (Vergleich)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="136"/>
        <source>The prusa-slicer program: a name found on PATH, or a full path</source>
        <translation>Das Programm prusa-slicer: ein Name, der im PATH gefunden wird, oder ein vollständiger Pfad</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="144"/>
        <source>Printer:</source>
        <translation>Drucker:</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="146"/>
        <source>Dialect:</source>
        <translation>Dialekt:</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="147"/>
        <source>Slicer settings:</source>
        <translation>Slicer-Einstellungen:</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="149"/>
        <source>Slicer program:</source>
        <translation>Slicer-Programm:</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="151"/>
        <source>Slice</source>
        <translation>Slicen</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="182"/>
        <source>Cannot use the printer profile: %1</source>
        <translation>Das Druckerprofil kann nicht verwendet werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="187"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="223"/>
        <source>Load a PrusaSlicer Printer Profile</source>
        <translation>PrusaSlicer-Druckerprofil laden</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="225"/>
        <source>PrusaSlicer profiles (*.ini);;All files (*)</source>
        <translation>PrusaSlicer-Profile (*.ini);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="240"/>
        <source>Choose a printer profile.</source>
        <translation>Wählen Sie ein Druckerprofil.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="246"/>
        <source>Slicer settings: %1</source>
        <translation>Slicer-Einstellungen: %1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_dialog.cpp" line="60"/>
        <source>A plan printed apart is sliced part by part on plates: use Search &gt; Print apart... or &apos;multidir apart&apos; (docs/apart.md).</source>
        <translation>Ein getrennt gedruckter Plan wird Teil für Teil auf Druckplatten gesliced: verwenden Sie Suche &gt; Getrennt drucken... oder „multidir apart“ (docs/apart.md).</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SliceJobRunner</name>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="52"/>
        <source>Slicing step %1 of %2</source>
        <translation>Slicen: Schritt %1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="54"/>
        <source>Slicing the whole model along up with the slicer&apos;s supports, for comparison</source>
        <translation>Slicen des ganzen Modells in Aufwärtsrichtung mit den Stützen des Slicers, zum Vergleich</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="56"/>
        <source>Stitching the steps into one program</source>
        <translation>Die Schritte werden zu einem Programm zusammengefügt</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="60"/>
        <source>Reading the G-code for the preview</source>
        <translation>G-Code wird für die Vorschau gelesen</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="66"/>
        <source>The slicer &apos;%1&apos; was not found: install PrusaSlicer (scripts/install-deps.sh) or give the slicer program&apos;s full path in the Slice dialog.</source>
        <translation>Der Slicer „%1“ wurde nicht gefunden: installieren Sie PrusaSlicer (scripts/install-deps.sh) oder geben Sie im Dialog „Plan slicen“ den vollständigen Pfad des Slicer-Programms an.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="71"/>
        <source>The slicer failed: its command and last output lines are below.</source>
        <translation>Der Slicer ist fehlgeschlagen: sein Befehl und die letzten Ausgabezeilen stehen unten.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="73"/>
        <source>The part does not fit this printer, so nothing was sliced: by how much, and what would help, is below.</source>
        <translation>Das Teil passt nicht auf diesen Drucker, daher wurde nichts geslict: um wie viel, und was helfen würde, steht unten.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="77"/>
        <source>The G-code failed MultiDir&apos;s checks and was not kept: the step, line and reason are below.</source>
        <translation>Der G-Code hat die Prüfungen von MultiDir nicht bestanden und wurde verworfen: Schritt, Zeile und Grund stehen unten.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="105"/>
        <source>A slicing job is already running.</source>
        <translation>Ein Slicing-Auftrag läuft bereits.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="142"/>
        <source>Could not create a temporary folder for the G-code: %1</source>
        <translation>Für den G-Code konnte kein temporärer Ordner angelegt werden: %1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="139"/>
        <source>Not enough memory to slice this plan.</source>
        <translation>Nicht genug Speicher, um diesen Plan zu slicen.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="133"/>
        <source>The audit of the G-code failed, so unsupported extrusions are not marked: %1</source>
        <translation>Die Prüfung des G-Codes ist fehlgeschlagen, daher sind ungestützte Extrusionen nicht markiert: %1</translation>
    </message>
    <message>
        <location filename="../ui/jobs/slice_job_runner.cpp" line="139"/>
        <source>Unexpected error while slicing.</source>
        <translation>Unerwarteter Fehler beim Slicen.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SlicePanel</name>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="44"/>
        <source>Slice...</source>
        <translation>Slicen...</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="46"/>
        <location filename="../ui/panels/slice_panel.cpp" line="153"/>
        <source>Slice every step of the plan shown, with its supports, into G-code (PrusaSlicer)</source>
        <translation>Jeden Schritt des angezeigten Plans mit seinen Stützen zu G-Code slicen (PrusaSlicer)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="47"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Print time</source>
        <translation>Druckzeit</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Filament (m)</source>
        <translation>Filament (m)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="64"/>
        <source>Filament (g)</source>
        <translation>Filament (g)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="83"/>
        <source>Export G-code...</source>
        <translation>G-Code exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="85"/>
        <source>Write step-NN.gcode, job.gcode (when the firmware turns the platform) and the print job with its estimates into a folder</source>
        <translation>step-NN.gcode, job.gcode (wenn die Firmware die Plattform dreht) und den Druckauftrag mit seinen Schätzungen in einen Ordner schreiben</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="87"/>
        <source>Preview G-code</source>
        <translation>G-Code-Vorschau</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="90"/>
        <source>Show the toolpaths in place of the regions; click again for the plan view</source>
        <translation>Die Werkzeugwege anstelle der Bereiche zeigen; erneut klicken für die Planansicht</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="93"/>
        <source>Show the layers printed up to this one (all steps, in printing order)</source>
        <translation>Die Schichten bis einschließlich dieser zeigen (alle Schritte, in Druckreihenfolge)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="98"/>
        <source>The layer&apos;s height: the nozzle&apos;s Z above the platform in its step&apos;s pose</source>
        <translation>Die Höhe der Schicht: das Z der Düse über der Plattform in der Lage ihres Schritts</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="100"/>
        <location filename="../ui/panels/slice_panel.cpp" line="266"/>
        <source>Z %1 mm</source>
        <translation>Z %1 mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="101"/>
        <source>Travel moves</source>
        <translation>Leerfahrten</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="75"/>
        <source>Extrusion that rests on nothing printed before it, as the audit finds it (multidir audit, check b): drawn in magenta in the G-code preview</source>
        <translation>Extrusion, die auf nichts zuvor Gedrucktem aufliegt, wie die Prüfung sie findet (multidir audit, Prüfung b): in der G-Code-Vorschau magenta gezeichnet</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="228"/>
        <source>Unsupported extrusion: %1 mm (%2 %) in magenta</source>
        <translation>Ungestützte Extrusion: %1 mm (%2 %) in Magenta</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="115"/>
        <source>Layers:</source>
        <translation>Schichten:</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="120"/>
        <source>G-code</source>
        <translation>G-Code</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="147"/>
        <source>Show a plan first: run a search or open a plan.</source>
        <translation>Zeigen Sie zuerst einen Plan an: starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="165"/>
        <source>Starting the slicer...</source>
        <translation>Slicer wird gestartet...</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="188"/>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="196"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="198"/>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="198"/>
        <source>Total (%1)</source>
        <translation>Gesamt (%1)</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="201"/>
        <source>Fixed direction, slicer supports</source>
        <translation>Feste Richtung, Slicer-Stützen</translation>
    </message>
    <message>
        <location filename="../ui/panels/slice_panel.cpp" line="203"/>
        <source>The whole model printed along up with PrusaSlicer&apos;s own supports: the comparison</source>
        <translation>Das ganze Modell in Aufwärtsrichtung mit den eigenen Stützen von PrusaSlicer gedruckt: der Vergleich</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/slice_panel.cpp" line="209"/>
        <source>Slower than the fixed direction: each of the %n steps starts anew (the platform turns, the nozzle lifts and primes, a first layer on the step&apos;s base), and here that costs more time than the slicer&apos;s supports it avoids.</source>
        <translation>
            <numerusform>Langsamer als die feste Richtung: jeder der %n Schritte beginnt neu (die Plattform dreht sich, die Düse hebt sich und spült vor, eine erste Schicht auf der Basis des Schritts), und das kostet hier mehr Zeit als die Stützen des Slicers, die dadurch entfallen.</numerusform>
            <numerusform>Langsamer als die feste Richtung: jeder der %n Schritte beginnt neu (die Plattform dreht sich, die Düse hebt sich und spült vor, eine erste Schicht auf der Basis des Schritts), und das kostet hier mehr Zeit als die Stützen des Slicers, die dadurch entfallen.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>multidir::ui::SliceSession</name>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="46"/>
        <location filename="../ui/slicing/slice_session.cpp" line="47"/>
        <source>Slicing failed: %1</source>
        <translation>Slicen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="53"/>
        <source>Slicing cancelled: nothing was written.</source>
        <translation>Slicen abgebrochen: nichts wurde geschrieben.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="54"/>
        <source>Slicing cancelled.</source>
        <translation>Slicen abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="63"/>
        <source>Show a plan first: run a search or open a plan.</source>
        <translation>Zeigen Sie zuerst einen Plan an: starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="65"/>
        <location filename="../ui/slicing/slice_session.cpp" line="122"/>
        <source>The plan&apos;s supports are still being grown: slice it when they are ready.</source>
        <translation>Die Stützen des Plans werden noch erzeugt: slicen Sie ihn, sobald sie fertig sind.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="78"/>
        <source>The plan changed: slicing was cancelled.</source>
        <translation>Der Plan hat sich geändert: das Slicen wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="80"/>
        <source>The plan changed: slice it again for its G-code.</source>
        <translation>Der Plan hat sich geändert: slicen Sie ihn erneut, um seinen G-Code zu erhalten.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="114"/>
        <source>There is no plan to slice: run a search or open a plan.</source>
        <translation>Es gibt keinen Plan zum Slicen: starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="118"/>
        <source>A slicing job is already running.</source>
        <translation>Ein Slicing-Auftrag läuft bereits.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="137"/>
        <source>Slicing without supports although the plan leaves risky area: %1</source>
        <translation>Slicen ohne Stützen, obwohl der Plan Risikofläche übrig lässt: %1</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="138"/>
        <source>no supports were grown for it.</source>
        <translation>für ihn wurden keine Stützen erzeugt.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="143"/>
        <source>Slicing the plan for %1...</source>
        <translation>Slicen des Plans für %1...</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="150"/>
        <source>Cancelling: stopping the slicer...</source>
        <translation>Abbruch: Slicer wird angehalten...</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/slicing/slice_session.cpp" line="165"/>
        <source>Sliced for %1: %n step(s), %2 of printing.</source>
        <translation>
            <numerusform>Slicen für %1 abgeschlossen: %n Schritt, %2 Druckzeit.</numerusform>
            <numerusform>Slicen für %1 abgeschlossen: %n Schritte, %2 Druckzeit.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="169"/>
        <source>Slicing finished.</source>
        <translation>Slicen abgeschlossen.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="170"/>
        <source>Slicing finished; the audit failed.</source>
        <translation>Slicen abgeschlossen; die Prüfung ist fehlgeschlagen.</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="205"/>
        <source>Layer %1 of %2: step %3, its layer %4</source>
        <translation>Schicht %1 von %2: Schritt %3, dessen Schicht %4</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="211"/>
        <source>There is no G-code to export: slice the plan first.</source>
        <translation>Es gibt keinen G-Code zum Exportieren: slicen Sie zuerst den Plan.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/slicing/slice_session.cpp" line="221"/>
        <source>G-code exported to %1 (%n file(s)).</source>
        <translation>
            <numerusform>G-Code nach %1 exportiert (%n Datei).</numerusform>
            <numerusform>G-Code nach %1 exportiert (%n Dateien).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="231"/>
        <source>Export G-code to Folder</source>
        <translation>G-Code in Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="231"/>
        <source>-gcode</source>
        <translation>-gcode</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="232"/>
        <source>G-code folders (*)</source>
        <translation>G-Code-Ordner (*)</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="238"/>
        <location filename="../ui/slicing/slice_session.cpp" line="245"/>
        <source>Export G-code</source>
        <translation>G-Code exportieren</translation>
    </message>
    <message>
        <location filename="../ui/slicing/slice_session.cpp" line="239"/>
        <source>%1 holds files that are not a MultiDir job (%2 is one).

Write the job into this folder anyway? Files with the job&apos;s names are replaced; the others stay.</source>
        <translation>%1 enthält Dateien, die nicht zu einem MultiDir-Auftrag gehören (%2 ist eine davon).

Den Auftrag trotzdem in diesen Ordner schreiben? Dateien mit den Namen des Auftrags werden ersetzt, die anderen bleiben.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::StudioDocument</name>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="143"/>
        <source>This job was sliced from another plan than the one shown: slice the plan shown again.</source>
        <translation>Dieser Auftrag wurde aus einem anderen als dem angezeigten Plan gesliced: slicen Sie den angezeigten Plan erneut.</translation>
    </message>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="190"/>
        <source>A print run already holds the device session&apos;s job: stop it before starting another.</source>
        <translation>Ein Drucklauf hält bereits den Auftrag der Gerätesitzung: beenden Sie ihn, bevor Sie einen anderen starten.</translation>
    </message>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="194"/>
        <source>There is no plan to run: run a search or open a plan first.</source>
        <translation>Es gibt keinen Plan zum Ausführen: führen Sie zuerst eine Suche aus oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/document/studio_document.cpp" line="163"/>
        <source>These parts were made from another plan than the one shown: print the plan shown apart again.</source>
        <translation>Diese Teile wurden aus einem anderen als dem angezeigten Plan erzeugt: drucken Sie den angezeigten Plan erneut getrennt.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::StudioStartup</name>
    <message>
        <location filename="../ui/studio_startup.cpp" line="62"/>
        <source>MultiDir Studio: plans multi-directional 3D prints.</source>
        <translation>MultiDir Studio: plant mehrrichtige 3D-Drucke.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="66"/>
        <source>Printing (up) direction of the model: x, -y, +z or a,b,c. Default: +z.</source>
        <translation>Druckrichtung (oben) des Modells: x, -y, +z oder a,b,c. Standard: +z.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="67"/>
        <source>direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="69"/>
        <source>Render the window to this PNG file and quit.</source>
        <translation>Das Fenster in diese PNG-Datei zeichnen und beenden.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="69"/>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="70"/>
        <source>Language of the user interface: de, zh_CN or en.</source>
        <translation>Sprache der Benutzeroberfläche: de, zh_CN oder en.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="71"/>
        <source>language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="73"/>
        <source>Run a search with the default settings once the model is shown.</source>
        <translation>Eine Suche mit den Standardeinstellungen starten, sobald das Modell angezeigt wird.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="74"/>
        <source>Maximal overhang angle in degrees (0-89).</source>
        <translation>Größter Überhangwinkel in Grad (0-89).</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="75"/>
        <source>degrees</source>
        <translation>Grad</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="82"/>
        <source>Mesh file (.stl .obj .off .ply) or MultiDir project (.multidir) to open. Default: the first sample.</source>
        <translation>Zu öffnende Netzdatei (.stl .obj .off .ply) oder MultiDir-Projekt (.multidir). Standard: das erste Beispiel.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="214"/>
        <source>The search or the project&apos;s plan did not finish within %1 s.</source>
        <translation>Die Suche oder der Plan des Projekts wurde nicht innerhalb von %1 s fertig.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="83"/>
        <source>[model]</source>
        <translation>[Modell]</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="88"/>
        <source>Try --help for usage.</source>
        <translation>Hinweise zur Verwendung mit --help.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="103"/>
        <source>Give at most one model; got %1.</source>
        <translation>Geben Sie höchstens ein Modell an; erhalten: %1.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="107"/>
        <source>--up: %1</source>
        <translation>--up: %1</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="113"/>
        <source>--lang: &apos;%1&apos; is not available; use de, zh_CN or en.</source>
        <translation>--lang: „%1“ ist nicht verfügbar; verwenden Sie de, zh_CN oder en.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="120"/>
        <source>--alpha must be a number from 0 to 89.</source>
        <translation>--alpha muss eine Zahl von 0 bis 89 sein.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="125"/>
        <source>--screenshot needs a file name.</source>
        <translation>--screenshot braucht einen Dateinamen.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="206"/>
        <source>The model did not finish loading within %1 s.</source>
        <translation>Das Modell wurde nicht innerhalb von %1 s fertig geladen.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="228"/>
        <source>No model is shown; the screenshot %1 shows the empty window.</source>
        <translation>Es wird kein Modell angezeigt; das Bildschirmfoto %1 zeigt das leere Fenster.</translation>
    </message>
</context>
</TS>
