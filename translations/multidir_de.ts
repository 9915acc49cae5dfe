<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>multidir::ui::ErrorText</name>
    <message>
        <location filename="../ui/error_text.cpp" line="18"/>
        <source>The file does not exist or cannot be read.</source>
        <translation>Die Datei existiert nicht oder kann nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="20"/>
        <source>This file type is not supported: use STL, OBJ, OFF or PLY.</source>
        <translation>Dieser Dateityp wird nicht unterstützt: verwenden Sie STL, OBJ, OFF oder PLY.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="22"/>
        <source>The file is damaged or does not follow its format.</source>
        <translation>Die Datei ist beschädigt oder entspricht nicht ihrem Format.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="24"/>
        <source>The model is larger than MultiDir accepts.</source>
        <translation>Das Modell ist größer, als MultiDir annimmt.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="26"/>
        <source>The file could not be written.</source>
        <translation>Die Datei konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="28"/>
        <source>The file contains no triangles.</source>
        <translation>Die Datei enthält keine Dreiecke.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="30"/>
        <source>Some vertex coordinates are not numbers.</source>
        <translation>Einige Eckpunktkoordinaten sind keine Zahlen.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="32"/>
        <source>The surface is not a clean solid: some edges or vertices are shared by too many faces.</source>
        <translation>Die Oberfläche ist kein sauberer Körper: einige Kanten oder Eckpunkte gehören zu zu vielen Flächen.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="35"/>
        <source>The surface has holes, so it does not enclose a solid. Close them in a mesh repair tool.</source>
        <translation>Die Oberfläche hat Löcher und umschließt daher keinen Körper. Schließen Sie sie mit einem Netzreparaturwerkzeug.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="38"/>
        <source>The faces of the surface point in inconsistent directions.</source>
        <translation>Die Flächen der Oberfläche zeigen in widersprüchliche Richtungen.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="40"/>
        <source>A setting is out of its allowed range.</source>
        <translation>Eine Einstellung liegt außerhalb ihres zulässigen Bereichs.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="42"/>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="46"/>
        <source>An internal error occurred: please report it with the model.</source>
        <translation>Ein interner Fehler ist aufgetreten: bitte melden Sie ihn zusammen mit dem Modell.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::JgChart</name>
    <message>
        <location filename="../ui/panels/jg_chart.cpp" line="27"/>
        <source>Level</source>
        <translation>Ebene</translation>
    </message>
    <message>
        <location filename="../ui/panels/jg_chart.cpp" line="32"/>
        <source>Best J_G (mm²)</source>
        <translation>Bestes J_G (mm²)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MachinePanel</name>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="26"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="42"/>
        <source>3-DOF: fixed printing direction</source>
        <translation>3-DOF: feste Druckrichtung</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="43"/>
        <source>4-DOF: rotary platform</source>
        <translation>4-DOF: Drehplattform</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="44"/>
        <source>5-DOF: tilting robot arm</source>
        <translation>5-DOF: kippender Roboterarm</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="47"/>
        <source>Rotary platform (4-DOF)</source>
        <translation>Drehplattform (4-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="50"/>
        <source>The axis the platform turns about, as x,y,z or x, -y, +z; it must lie in the platform plane (perpendicular to up)</source>
        <translation>Die Achse, um die sich die Plattform dreht, als x,y,z oder x, -y, +z; sie muss in der Plattformebene liegen (senkrecht zu oben)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="55"/>
        <source>The stepper&apos;s resolution: only multiples of this angle can be reached</source>
        <translation>Auflösung des Schrittmotors: nur Vielfache dieses Winkels sind erreichbar</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="57"/>
        <source>Rotation axis:</source>
        <translation>Drehachse:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="58"/>
        <source>Minimal angle:</source>
        <translation>Kleinster Winkel:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="59"/>
        <source>Maximal angle:</source>
        <translation>Größter Winkel:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="60"/>
        <source>Angle step:</source>
        <translation>Winkelschritt:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="62"/>
        <source>Tilting arm (5-DOF)</source>
        <translation>Kipparm (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="64"/>
        <source>How far the arm can tilt the platform away from up</source>
        <translation>Wie weit der Arm die Plattform aus der Senkrechten kippen kann</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="66"/>
        <source>Tilt limit:</source>
        <translation>Kippgrenze:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="72"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="73"/>
        <source>model footprint</source>
        <translation>Modellgrundfläche</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="75"/>
        <source>Radius of the platform disc that no clipping plane may cut; 0 uses the model&apos;s footprint plus a margin</source>
        <translation>Radius der Plattformscheibe, die keine Schnittebene schneiden darf; 0 nimmt die Grundfläche des Modells plus einen Rand</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="85"/>
        <source>Machine:</source>
        <translation>Maschine:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="86"/>
        <source>Platform radius:</source>
        <translation>Plattformradius:</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="151"/>
        <source>The rotation axis &quot;%1&quot; cannot be read: type three numbers x,y,z or an axis such as x or -y.</source>
        <translation>Die Drehachse „%1“ ist nicht lesbar: Geben Sie drei Zahlen x,y,z oder eine Achse wie x oder -y ein.</translation>
    </message>
    <message>
        <location filename="../ui/panels/machine_panel.cpp" line="156"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>multidir::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="63"/>
        <source>MultiDir Studio</source>
        <translation>MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="86"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="87"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="89"/>
        <source>Open a mesh file (STL, OBJ, OFF or PLY)</source>
        <translation>Eine Netzdatei öffnen (STL, OBJ, OFF oder PLY)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="91"/>
        <source>&amp;Samples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="100"/>
        <source>Open &amp;plan...</source>
        <translation>&amp;Plan öffnen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="102"/>
        <source>Show a plan saved earlier (a folder with plan.json)</source>
        <translation>Einen früher gespeicherten Plan anzeigen (ein Ordner mit plan.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="103"/>
        <source>&amp;Export plan...</source>
        <translation>Plan &amp;exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="105"/>
        <source>Save the plan shown: plan.json and one STL per region</source>
        <translation>Den angezeigten Plan speichern: plan.json und eine STL-Datei je Bereich</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="108"/>
        <source>&amp;Load machine profile...</source>
        <translation>Maschinenprofil &amp;laden...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="110"/>
        <source>&amp;Save machine profile...</source>
        <translation>Maschinenprofil &amp;speichern...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="113"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="116"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="117"/>
        <source>&amp;Fit to View</source>
        <translation>In Ansicht ein&amp;passen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="119"/>
        <source>Show the &amp;model (hide the plan)</source>
        <translation>&amp;Modell zeigen (Plan ausblenden)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="124"/>
        <source>&amp;Search</source>
        <translation>&amp;Suche</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="125"/>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="127"/>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="144"/>
        <source>Overhangs</source>
        <translation>Überhänge</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="145"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="146"/>
        <source>Search</source>
        <translation>Suche</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="147"/>
        <source>Plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="172"/>
        <source>Printing direction</source>
        <translation>Druckrichtung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="175"/>
        <source>Up:</source>
        <translation>Oben:</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="180"/>
        <source>The direction the model is printed along: the platform is below, overhangs are measured against it</source>
        <translation>Die Richtung, in der das Modell gedruckt wird: die Plattform liegt darunter, Überhänge werden daran gemessen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="185"/>
        <source>+X</source>
        <translation>+X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="185"/>
        <source>-X</source>
        <translation>-X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="186"/>
        <source>+Y</source>
        <translation>+Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="186"/>
        <source>-Y</source>
        <translation>-Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="187"/>
        <source>+Z</source>
        <translation>+Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="187"/>
        <source>-Z</source>
        <translation>-Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="228"/>
        <source>Open Model</source>
        <translation>Modell öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="229"/>
        <source>Meshes (*.stl *.obj *.off *.ply);;All files (*)</source>
        <translation>Netze (*.stl *.obj *.off *.ply);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="245"/>
        <source>Custom (%1, %2, %3)</source>
        <translation>Benutzerdefiniert (%1, %2, %3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="266"/>
        <source>%1 - MultiDir Studio</source>
        <translation>%1 - MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="270"/>
        <source>Repaired on load: %1</source>
        <translation>Beim Laden repariert: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="284"/>
        <source>Could not open %1: %2</source>
        <translation>%1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="288"/>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="292"/>
        <source>%1 is still open.</source>
        <translation>%1 ist weiterhin geöffnet.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="311"/>
        <location filename="../ui/main_window.cpp" line="328"/>
        <source>No model</source>
        <translation>Kein Modell</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="321"/>
        <source>Triangles: %1</source>
        <translation>Dreiecke: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="322"/>
        <source>Volume: %1 mm³</source>
        <translation>Volumen: %1 mm³</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="336"/>
        <source>Risky area unavailable</source>
        <translation>Risikofläche nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="344"/>
        <source>Risky area (%1 up): %2 mm²</source>
        <translation>Risikofläche (%1 oben): %2 mm²</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="346"/>
        <source>Area of the faces that overhang by more than %1° for this up direction</source>
        <translation>Fläche der Dreiecke, die bei dieser Aufwärtsrichtung um mehr als %1° überhängen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="361"/>
        <location filename="../ui/main_window.cpp" line="380"/>
        <source>Open a model first.</source>
        <translation>Öffnen Sie zuerst ein Modell.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="363"/>
        <source>Fix the machine first: %1</source>
        <translation>Korrigieren Sie zuerst die Maschine: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="379"/>
        <source>A search is already running.</source>
        <translation>Eine Suche läuft bereits.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="385"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="389"/>
        <source>Cannot search: %1</source>
        <translation>Suche nicht möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="390"/>
        <source>Cannot search.</source>
        <translation>Suche nicht möglich.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="404"/>
        <source>Searching %1...</source>
        <translation>Durchsuche %1...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="412"/>
        <source>Cancelling the search...</source>
        <translation>Suche wird abgebrochen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="420"/>
        <source>The search result was dropped: the model or its up direction changed.</source>
        <translation>Das Suchergebnis wurde verworfen: das Modell oder seine Aufwärtsrichtung hat sich geändert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="423"/>
        <source>Search cancelled: showing the best plan found so far.</source>
        <translation>Suche abgebrochen: der bisher beste Plan wird angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="424"/>
        <source>Search finished.</source>
        <translation>Suche beendet.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="432"/>
        <source>Search failed: %1</source>
        <translation>Suche fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="459"/>
        <source>There is no plan to export: run a search first.</source>
        <translation>Es gibt keinen Plan zum Exportieren: starten Sie zuerst eine Suche.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="473"/>
        <source>Could not export the plan to %1: %2 (%3)</source>
        <translation>Der Plan konnte nicht nach %1 exportiert werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="476"/>
        <source>Plan exported to %1.</source>
        <translation>Plan nach %1 exportiert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="483"/>
        <source>Could not open the plan %1: %2 (%3)</source>
        <translation>Der Plan %1 konnte nicht geöffnet werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="528"/>
        <source>Machine profile saved to %1.</source>
        <translation>Maschinenprofil unter %1 gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="540"/>
        <source>Machine profile %1 loaded.</source>
        <translation>Maschinenprofil %1 geladen.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="545"/>
        <source>Export Plan to Folder</source>
        <translation>Plan in Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="548"/>
        <source>Export Plan</source>
        <translation>Plan exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="552"/>
        <source>Open Plan Folder</source>
        <translation>Planordner öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="555"/>
        <source>Open Plan</source>
        <translation>Plan öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="559"/>
        <location filename="../ui/main_window.cpp" line="563"/>
        <source>Save Machine Profile</source>
        <translation>Maschinenprofil speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="560"/>
        <source>Machine profiles (*.json)</source>
        <translation>Maschinenprofile (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="567"/>
        <location filename="../ui/main_window.cpp" line="571"/>
        <source>Load Machine Profile</source>
        <translation>Maschinenprofil laden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="568"/>
        <source>Machine profiles (*.json);;All files (*)</source>
        <translation>Maschinenprofile (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="575"/>
        <source>Loading %1...</source>
        <translation>Lade %1...</translation>
    </message>
</context>
<context>
    <name>multidir::ui::ModelLoader</name>
    <message>
        <location filename="../ui/jobs/model_loader.cpp" line="50"/>
        <source>Not enough memory to load this model.</source>
        <translation>Nicht genug Speicher, um dieses Modell zu laden.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/model_loader.cpp" line="53"/>
        <location filename="../ui/jobs/model_loader.cpp" line="57"/>
        <source>Unexpected error while loading.</source>
        <translation>Unerwarteter Fehler beim Laden.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::OverhangPanel</name>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="25"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="29"/>
        <source>Maximal self-supporting angle: faces that lean over by more than this from the printing direction need support</source>
        <translation>Größter selbsttragender Winkel: Flächen, die stärker als dieser Winkel überhängen, brauchen Stützen</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="58"/>
        <source>Risky faces (need support when printed along the up direction)</source>
        <translation>Risikoflächen (brauchen Stützen beim Druck in Aufwärtsrichtung)</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="61"/>
        <source>Max. overhang angle α:</source>
        <translation>Max. Überhangwinkel α:</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="62"/>
        <source>Risky area:</source>
        <translation>Risikofläche:</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="63"/>
        <source>Risky faces:</source>
        <translation>Risikoflächen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="68"/>
        <source>No model</source>
        <translation>Kein Modell</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="76"/>
        <source>%1 mm²</source>
        <translation>%1 mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="78"/>
        <source>%1 of %2</source>
        <translation>%1 von %2</translation>
    </message>
    <message>
        <location filename="../ui/panels/overhang_panel.cpp" line="83"/>
        <source>unavailable</source>
        <translation>nicht verfügbar</translation>
    </message>
</context>
<context>
    <name>multidir::ui::PlanPanel</name>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="45"/>
        <location filename="../ui/panels/plan_panel.cpp" line="156"/>
        <source>No plan yet: run a search or open a plan.</source>
        <translation>Noch kein Plan: starten Sie eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="52"/>
        <source>Region</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="52"/>
        <source>Volume (mm³)</source>
        <translation>Volumen (mm³)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="52"/>
        <source>Risky (mm²)</source>
        <translation>Risiko (mm²)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="52"/>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="52"/>
        <source>Machine angles</source>
        <translation>Maschinenwinkel</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="60"/>
        <source>Printing directions</source>
        <translation>Druckrichtungen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="63"/>
        <source>Clipping planes</source>
        <translation>Schnittebenen</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="65"/>
        <source>Turn the view as the machine turns the part</source>
        <translation>Ansicht drehen, wie die Maschine das Teil dreht</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="70"/>
        <source>Moves the regions apart along their printing directions</source>
        <translation>Schiebt die Bereiche entlang ihrer Druckrichtungen auseinander</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="77"/>
        <source>Previous region</source>
        <translation>Vorheriger Bereich</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="80"/>
        <source>Next region</source>
        <translation>Nächster Bereich</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="89"/>
        <source>Show:</source>
        <translation>Anzeigen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="91"/>
        <source>Exploded view:</source>
        <translation>Explosionsansicht:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="92"/>
        <source>Printed up to:</source>
        <translation>Gedruckt bis:</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="126"/>
        <source>none (fixed)</source>
        <translation>keine (fest)</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="128"/>
        <source>rotary %1°</source>
        <translation>Drehung %1°</translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="131"/>
        <source>tilt %1°, azimuth %2°</source>
        <translation>Neigung %1°, Azimut %2°</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/plan_panel.cpp" line="137"/>
        <source>%n region(s); J_G %1 mm² before, %2 mm² after.</source>
        <translation>
            <numerusform>%n Bereich; J_G vorher %1 mm², nachher %2 mm².</numerusform>
            <numerusform>%n Bereiche; J_G vorher %1 mm², nachher %2 mm².</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/plan_panel.cpp" line="186"/>
        <source>of %1</source>
        <translation>von %1</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SearchJob</name>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="91"/>
        <source>Not enough memory for this search: lower the beam width or the number of normals.</source>
        <translation>Nicht genug Speicher für diese Suche: verringern Sie die Strahlbreite oder die Zahl der Normalen.</translation>
    </message>
    <message>
        <location filename="../ui/jobs/search_job.cpp" line="94"/>
        <location filename="../ui/jobs/search_job.cpp" line="98"/>
        <source>Unexpected error during the search.</source>
        <translation>Unerwarteter Fehler während der Suche.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::SearchPanel</name>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="36"/>
        <source>Beam search (Algorithm 1)</source>
        <translation>Strahlsuche (Algorithmus 1)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="37"/>
        <source>Constrained greedy</source>
        <translation>Eingeschränkt gierig</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="38"/>
        <source>Greedy</source>
        <translation>Gierig</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="43"/>
        <source>How many partial plans each level keeps (b)</source>
        <translation>Wie viele Teilpläne jede Ebene behält (b)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="49"/>
        <source>w: every region cut off keeps at least the model&apos;s volume divided by w</source>
        <translation>w: jeder abgetrennte Bereich behält mindestens das Modellvolumen geteilt durch w</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="54"/>
        <source>Candidate normals sampled on the whole sphere (5-DOF)</source>
        <translation>Kandidatennormalen, auf der ganzen Kugel abgetastet (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="59"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="61"/>
        <source>Distance between candidate planes along each normal</source>
        <translation>Abstand der Kandidatenebenen entlang jeder Normalen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="66"/>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="68"/>
        <source>Maximal self-supporting angle the search plans for</source>
        <translation>Größter selbsttragender Winkel, mit dem die Suche plant</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="73"/>
        <source>machine&apos;s axis only</source>
        <translation>nur Achse der Maschine</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="74"/>
        <source>4-DOF: also try this many rotation axes spread over 180° and keep the best</source>
        <translation>4-DOF: zusätzlich so viele über 180° verteilte Drehachsen probieren und die beste behalten</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="77"/>
        <source>Scheme:</source>
        <translation>Verfahren:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="78"/>
        <source>Beam width:</source>
        <translation>Strahlbreite:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="79"/>
        <source>Volume divisor w:</source>
        <translation>Volumenteiler w:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="80"/>
        <source>Normals:</source>
        <translation>Normalen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="81"/>
        <source>Offset step:</source>
        <translation>Versatzschritt:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="82"/>
        <source>Max. overhang angle α:</source>
        <translation>Max. Überhangwinkel α:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="83"/>
        <source>Axes to try:</source>
        <translation>Zu probierende Achsen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="86"/>
        <source>&amp;Run search</source>
        <translation>Suche &amp;starten</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="89"/>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="104"/>
        <source>Progress</source>
        <translation>Fortschritt</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="112"/>
        <source>Level:</source>
        <translation>Ebene:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="113"/>
        <source>Beams alive:</source>
        <translation>Aktive Strahlen:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="114"/>
        <source>Best J_G:</source>
        <translation>Bestes J_G:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="115"/>
        <source>Candidates scored:</source>
        <translation>Bewertete Kandidaten:</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="136"/>
        <source>Open a model first.</source>
        <translation>Öffnen Sie zuerst ein Modell.</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="174"/>
        <source>Search for clipping planes that make the model printable with less support</source>
        <translation>Nach Schnittebenen suchen, mit denen das Modell mit weniger Stützen druckbar wird</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="192"/>
        <source>Starting...</source>
        <translation>Starte...</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="195"/>
        <location filename="../ui/panels/search_panel.cpp" line="214"/>
        <location filename="../ui/panels/search_panel.cpp" line="228"/>
        <source>%1 mm²</source>
        <translation>%1 mm²</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="211"/>
        <source>%1 (axis %2 of %3)</source>
        <translation>%1 (Achse %2 von %3)</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="221"/>
        <source>Cancelling: keeping the best plan so far...</source>
        <translation>Abbruch: der bisher beste Plan wird behalten...</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="227"/>
        <source>Cancelled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="227"/>
        <source>Done</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="233"/>
        <source>Cancelled: showing the best plan found so far.</source>
        <translation>Abgebrochen: der bisher beste Plan wird angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="237"/>
        <source>Nothing improved: no clipping plane lowers the risky area (J_G stays %1 mm²). Try more normals, a smaller offset step, a larger w or another machine.</source>
        <translation>Keine Verbesserung: keine Schnittebene verringert die Risikofläche (J_G bleibt %1 mm²). Versuchen Sie mehr Normalen, einen kleineren Versatzschritt, ein größeres w oder eine andere Maschine.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/search_panel.cpp" line="242"/>
        <source>Not support-free: %1 mm² still needs support (was %2 mm²), in %n region(s).</source>
        <translation>
            <numerusform>Nicht stützenfrei: %1 mm² brauchen noch Stützen (vorher %2 mm²), in %n Bereich.</numerusform>
            <numerusform>Nicht stützenfrei: %1 mm² brauchen noch Stützen (vorher %2 mm²), in %n Bereichen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/panels/search_panel.cpp" line="246"/>
        <source>Support-free in %n region(s) (J_G was %1 mm²).</source>
        <translation>
            <numerusform>Stützenfrei in %n Bereich (J_G war %1 mm²).</numerusform>
            <numerusform>Stützenfrei in %n Bereichen (J_G war %1 mm²).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="254"/>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../ui/panels/search_panel.cpp" line="255"/>
        <source>%1
%2</source>
        <translation>%1
%2</translation>
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
        <source>Mesh file to open (.stl .obj .off .ply). Default: the first sample.</source>
        <translation>Zu öffnende Netzdatei (.stl .obj .off .ply). Standard: das erste Beispiel.</translation>
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
        <location filename="../ui/studio_startup.cpp" line="196"/>
        <source>The model did not finish loading within %1 s.</source>
        <translation>Das Modell wurde nicht innerhalb von %1 s fertig geladen.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="202"/>
        <source>The search did not finish within %1 s.</source>
        <translation>Die Suche wurde nicht innerhalb von %1 s fertig.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="212"/>
        <source>Could not write the screenshot to %1.</source>
        <translation>Das Bildschirmfoto konnte nicht nach %1 geschrieben werden.</translation>
    </message>
    <message>
        <location filename="../ui/studio_startup.cpp" line="216"/>
        <source>No model is shown; the screenshot %1 shows the empty window.</source>
        <translation>Es wird kein Modell angezeigt; das Bildschirmfoto %1 zeigt das leere Fenster.</translation>
    </message>
</context>
</TS>
