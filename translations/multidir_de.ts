<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>multidir::ui::ConnectionForm</name>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="36"/>
        <source>Rotary platform (4-DOF)</source>
        <translation>Drehplattform (4-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="37"/>
        <source>Robot arm (5-DOF)</source>
        <translation>Roboterarm (5-DOF)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="41"/>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="42"/>
        <source>Modbus RTU (serial)</source>
        <translation>Modbus RTU (seriell)</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="51"/>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="52"/>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="53"/>
        <source>Unit id:</source>
        <translation>Unit-ID:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="68"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="69"/>
        <source>Even</source>
        <translation>Gerade</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="70"/>
        <source>Odd</source>
        <translation>Ungerade</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="74"/>
        <source>Serial port:</source>
        <translation>Serielle Schnittstelle:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="75"/>
        <source>Baud:</source>
        <translation>Baudrate:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="76"/>
        <source>Parity:</source>
        <translation>Parität:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="77"/>
        <source>Data bits:</source>
        <translation>Datenbits:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="78"/>
        <source>Stop bits:</source>
        <translation>Stoppbits:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="79"/>
        <source>Slave id:</source>
        <translation>Slave-ID:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="86"/>
        <location filename="../ui/device/connection_form.cpp" line="89"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="87"/>
        <source>How long to wait for the first byte of a reply, and for a TCP connection.</source>
        <translation>Wie lange auf das erste Byte einer Antwort und auf eine TCP-Verbindung gewartet wird.</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="90"/>
        <source>How long to wait between two bytes of one reply.</source>
        <translation>Wie lange zwischen zwei Bytes einer Antwort gewartet wird.</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="99"/>
        <source> °/s</source>
        <translation> °/s</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="100"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="101"/>
        <source>Of the robot program&apos;s maximal rotation speed.</source>
        <translation>Anteil an der größten Drehgeschwindigkeit des Roboterprogramms.</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="102"/>
        <location filename="../ui/device/connection_form.cpp" line="103"/>
        <source>Speed:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="107"/>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="108"/>
        <source>Transport:</source>
        <translation>Übertragung:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="111"/>
        <source>Response timeout:</source>
        <translation>Antwort-Timeout:</translation>
    </message>
    <message>
        <location filename="../ui/device/connection_form.cpp" line="112"/>
        <source>Byte timeout:</source>
        <translation>Byte-Timeout:</translation>
    </message>
</context>
<context>
    <name>multidir::ui::DeviceLink</name>
    <message>
        <location filename="../ui/device/device_link.cpp" line="29"/>
        <source>stall: the platform made no progress, so MultiDir stopped it</source>
        <translation>blockiert: die Plattform kam nicht voran, daher hat MultiDir sie angehalten</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="30"/>
        <source>stall: the controller lost its position (following error)</source>
        <translation>blockiert: die Steuerung hat ihre Position verloren (Schleppfehler)</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="33"/>
        <source>heartbeat lost: the controller stopped because MultiDir went silent</source>
        <translation>Heartbeat verloren: die Steuerung hat angehalten, weil MultiDir nicht mehr antwortete</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="36"/>
        <source>a limit switch was hit</source>
        <translation>ein Endschalter wurde ausgelöst</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="39"/>
        <source>the controller rejected a command (not homed, or beyond its own limits)</source>
        <translation>die Steuerung hat einen Befehl abgelehnt (nicht referenziert oder außerhalb ihrer eigenen Grenzen)</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="42"/>
        <source>emergency stop: the power stage is off</source>
        <translation>Not-Halt: die Endstufe ist ausgeschaltet</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="45"/>
        <source>unknown fault code %1</source>
        <translation>unbekannter Fehlercode %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="48"/>
        <source>; press Clear fault, then Enable and Home</source>
        <translation>; drücken Sie „Fehler löschen“, dann „Aktivieren“ und „Referenzfahrt“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="54"/>
        <source>the robot program is not running: start it on the teach pendant</source>
        <translation>das Roboterprogramm läuft nicht: starten Sie es am Handbediengerät</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="56"/>
        <source>halted by an emergency stop: press Clear fault before moving again</source>
        <translation>durch einen Not-Halt angehalten: drücken Sie „Fehler löschen“, bevor Sie wieder verfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="60"/>
        <source>the target was beyond the robot program&apos;s limits; press Clear fault</source>
        <translation>das Ziel lag außerhalb der Grenzen des Roboterprogramms; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="62"/>
        <source>the robot stopped because MultiDir&apos;s heartbeat was lost; press Clear fault</source>
        <translation>der Roboter hat angehalten, weil der Heartbeat von MultiDir ausblieb; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="64"/>
        <source>the robot program got an unknown command; press Clear fault</source>
        <translation>das Roboterprogramm hat einen unbekannten Befehl erhalten; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="66"/>
        <source>robot program fault code %1; press Clear fault</source>
        <translation>Fehlercode %1 des Roboterprogramms; drücken Sie „Fehler löschen“</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="210"/>
        <source>Cannot connect with these settings: %1</source>
        <translation>Mit diesen Einstellungen ist keine Verbindung möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="213"/>
        <source>Could not connect yet; MultiDir keeps trying. %1</source>
        <translation>Noch keine Verbindung; MultiDir versucht es weiter. %1</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="241"/>
        <source>Enable</source>
        <translation>Aktivieren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="244"/>
        <source>%1 does not apply to the robot arm: its program enables the arm; start it on the teach pendant.</source>
        <translation>%1 gilt nicht für den Roboterarm: sein Programm aktiviert den Arm; starten Sie es am Handbediengerät.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="254"/>
        <source>Home</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="261"/>
        <source>Go to %1</source>
        <translation>%1 anfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="264"/>
        <source>%1 refused: the robot arm takes a tilt and an azimuth.</source>
        <translation>%1 abgelehnt: der Roboterarm erwartet eine Neigung und einen Azimut.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="271"/>
        <source>Go to tilt %1, azimuth %2</source>
        <translation>Neigung %1, Azimut %2 anfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="274"/>
        <source>%1 refused: the rotary platform takes one angle.</source>
        <translation>%1 abgelehnt: die Drehplattform erwartet einen einzigen Winkel.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="281"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="287"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="293"/>
        <source>Clear fault</source>
        <translation>Fehler löschen</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="308"/>
        <source>%1 refused: not connected; connect to the device first.</source>
        <translation>%1 abgelehnt: nicht verbunden; verbinden Sie zuerst das Gerät.</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="320"/>
        <source>%1 refused, nothing was sent: %2</source>
        <translation>%1 abgelehnt, nichts wurde gesendet: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="322"/>
        <source>%1 cancelled by Stop, E-STOP or Disconnect: %2</source>
        <translation>%1 durch Stopp, NOT-HALT oder Trennen abgebrochen: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/device_link.cpp" line="324"/>
        <source>%1 failed at the device or on the link: %2</source>
        <translation>%1 ist am Gerät oder auf der Verbindung fehlgeschlagen: %2</translation>
    </message>
</context>
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
        <location filename="../ui/error_text.cpp" line="44"/>
        <source>The device does not answer: check its power, cable or network.</source>
        <translation>Das Gerät antwortet nicht: prüfen Sie Stromversorgung, Kabel oder Netzwerk.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="46"/>
        <source>The device reported an error.</source>
        <translation>Das Gerät hat einen Fehler gemeldet.</translation>
    </message>
    <message>
        <location filename="../ui/error_text.cpp" line="50"/>
        <source>An internal error occurred: please report it with the model.</source>
        <translation>Ein interner Fehler ist aufgetreten: bitte melden Sie ihn zusammen mit dem Modell.</translation>
    </message>
</context>
<context>
    <name>multidir::ui::HardwarePanel</name>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="57"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="59"/>
        <source>Reconnecting…</source>
        <translation>Verbindung wird wiederhergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="60"/>
        <source>Connecting…</source>
        <translation>Verbindung wird hergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="62"/>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="64"/>
        <source>Fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="72"/>
        <source>idle</source>
        <translation>im Leerlauf</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="74"/>
        <source>turning the platform</source>
        <translation>Plattform wird gedreht</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="76"/>
        <source>settling</source>
        <translation>Beruhigungszeit</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="78"/>
        <source>printing</source>
        <translation>Druck läuft</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="80"/>
        <source>paused</source>
        <translation>pausiert</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="82"/>
        <source>finished</source>
        <translation>abgeschlossen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="84"/>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="86"/>
        <source>stopped by a device problem</source>
        <translation>durch ein Geräteproblem angehalten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="93"/>
        <source>angle %1</source>
        <translation>Winkel %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="94"/>
        <location filename="../ui/device/hardware_panel.cpp" line="373"/>
        <source>tilt %1, azimuth %2</source>
        <translation>Neigung %1, Azimut %2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="163"/>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="166"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="167"/>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="168"/>
        <source>Closes the link without commanding the device; its heartbeat watchdog stops it.</source>
        <translation>Schließt die Verbindung, ohne dem Gerät einen Befehl zu senden; sein Heartbeat-Watchdog hält es an.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="182"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="191"/>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="192"/>
        <source>Position:</source>
        <translation>Position:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="193"/>
        <source>Moving:</source>
        <translation>In Bewegung:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="194"/>
        <source>Homed:</source>
        <translation>Referenziert:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="195"/>
        <source>Fault:</source>
        <translation>Fehler:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="196"/>
        <source>Heartbeat:</source>
        <translation>Heartbeat:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="197"/>
        <source>Last problem:</source>
        <translation>Letztes Problem:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="202"/>
        <source>Controls</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="203"/>
        <source>Enable</source>
        <translation>Aktivieren</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="203"/>
        <source>Switches the platform&apos;s drive on.</source>
        <translation>Schaltet den Antrieb der Plattform ein.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="204"/>
        <source>Home</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="205"/>
        <source>Rotary platform: finds the home switch (0°). Robot arm: levels the platform (tilt 0°).</source>
        <translation>Drehplattform: sucht den Referenzschalter (0°). Roboterarm: richtet die Plattform waagerecht aus (Neigung 0°).</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="206"/>
        <source>Clear fault</source>
        <translation>Fehler löschen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="207"/>
        <source>Resets the device after a fault or an E-STOP; then enable and home again.</source>
        <translation>Setzt das Gerät nach einem Fehler oder NOT-HALT zurück; danach erneut aktivieren und referenzieren.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="211"/>
        <source>Tilt</source>
        <translation>Neigung</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="212"/>
        <source>Azimuth</source>
        <translation>Azimut</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="213"/>
        <source>Jog −</source>
        <translation>Tippen −</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="214"/>
        <source>Jog +</source>
        <translation>Tippen +</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="218"/>
        <source>Angle:</source>
        <translation>Winkel:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="219"/>
        <source>Tilt:</source>
        <translation>Neigung:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="220"/>
        <source>Azimuth:</source>
        <translation>Azimut:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="221"/>
        <source>Go to</source>
        <translation>Anfahren</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="223"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="223"/>
        <source>Decelerates and stops; cancels queued commands.</source>
        <translation>Bremst ab und hält an; verwirft wartende Befehle.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="224"/>
        <source>E-STOP</source>
        <translation>NOT-HALT</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="225"/>
        <source>Emergency stop: cuts the motion at once. Clear the fault, enable and home again afterwards.</source>
        <translation>Not-Halt: unterbricht die Bewegung sofort. Danach den Fehler löschen, erneut aktivieren und referenzieren.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="235"/>
        <source>Jog step:</source>
        <translation>Tippschritt:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="262"/>
        <source>Print run</source>
        <translation>Drucklauf</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="264"/>
        <location filename="../ui/device/hardware_panel.cpp" line="456"/>
        <source>Start run</source>
        <translation>Lauf starten</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="265"/>
        <source>Turns the platform to each region&apos;s orientation in printing order and asks for each region to be printed.</source>
        <translation>Dreht die Plattform in Druckreihenfolge in die Ausrichtung jedes Bereichs und fordert dazu auf, jeden Bereich zu drucken.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="274"/>
        <location filename="../ui/device/hardware_panel.cpp" line="303"/>
        <source>Region done</source>
        <translation>Bereich fertig</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="275"/>
        <source>Press when the region asked for has been printed.</source>
        <translation>Drücken, sobald der angeforderte Bereich gedruckt ist.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="276"/>
        <location filename="../ui/device/hardware_panel.cpp" line="304"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="277"/>
        <location filename="../ui/device/hardware_panel.cpp" line="305"/>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="278"/>
        <source>Continues a paused run, or retries the current step after a device problem.</source>
        <translation>Setzt einen pausierten Lauf fort oder wiederholt nach einem Geräteproblem den aktuellen Schritt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="279"/>
        <location filename="../ui/device/hardware_panel.cpp" line="306"/>
        <source>Abort</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="292"/>
        <source>Step:</source>
        <translation>Schritt:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="293"/>
        <source>Elapsed:</source>
        <translation>Verstrichen:</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="345"/>
        <source>Cannot connect with these settings: %1</source>
        <translation>Mit diesen Einstellungen ist keine Verbindung möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="349"/>
        <source>Connecting to %1…</source>
        <translation>Verbindung mit %1 wird hergestellt…</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="357"/>
        <source>Disconnected.</source>
        <translation>Getrennt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="369"/>
        <source>%1 (target %2)</source>
        <translation>%1 (Ziel %2)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="370"/>
        <source>homing</source>
        <translation>Referenzfahrt läuft</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="370"/>
        <location filename="../ui/device/hardware_panel.cpp" line="371"/>
        <location filename="../ui/device/hardware_panel.cpp" line="374"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="370"/>
        <location filename="../ui/device/hardware_panel.cpp" line="371"/>
        <location filename="../ui/device/hardware_panel.cpp" line="374"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="375"/>
        <source>not needed (robot arm)</source>
        <translation>nicht nötig (Roboterarm)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="377"/>
        <location filename="../ui/device/hardware_panel.cpp" line="379"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="386"/>
        <source>%1: sent to the device.</source>
        <translation>%1: an das Gerät gesendet.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="393"/>
        <source>Connected to %1.</source>
        <translation>Verbunden mit %1.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="402"/>
        <source>The print run stopped: %1. Fix the device (Clear fault, Enable, Home), then press Resume to retry this step, or Abort.</source>
        <translation>Der Drucklauf wurde angehalten: %1. Bringen Sie das Gerät in Ordnung (Fehler löschen, Aktivieren, Referenzfahrt) und drücken Sie dann „Fortsetzen“, um diesen Schritt zu wiederholen, oder „Abbrechen“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="407"/>
        <source>The print run is finished: every region was printed.</source>
        <translation>Der Drucklauf ist abgeschlossen: jeder Bereich wurde gedruckt.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="409"/>
        <source>The print run was aborted.</source>
        <translation>Der Drucklauf wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="416"/>
        <source>Print region %1 (file %2), then press Region done.</source>
        <translation>Drucken Sie Bereich %1 (Datei %2) und drücken Sie dann „Bereich fertig“.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="443"/>
        <source>Start run refused: not connected; connect to the device first.</source>
        <translation>„Lauf starten“ abgelehnt: nicht verbunden; verbinden Sie zuerst das Gerät.</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="450"/>
        <source>Start run refused: %1</source>
        <translation>„Lauf starten“ abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="460"/>
        <source>%1 refused: %2</source>
        <translation>%1 abgelehnt: %2</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="478"/>
        <source>Limits: %1 to %2 in steps of %3</source>
        <translation>Grenzen: %1 bis %2 in Schritten von %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="480"/>
        <source>Limits: tilt up to %1, %n forbidden cone(s)</source>
        <translation>
            <numerusform>Grenzen: Neigung bis %1, %n verbotener Kegel</numerusform>
            <numerusform>Grenzen: Neigung bis %1, %n verbotene Kegel</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="483"/>
        <source> (machine profile)</source>
        <translation> (Maschinenprofil)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="485"/>
        <source> (defaults: the machine profile is for a %1 machine)</source>
        <translation> (Standardwerte: das Maschinenprofil gilt für eine %1-Maschine)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="488"/>
        <source> (defaults: no machine profile)</source>
        <translation> (Standardwerte: kein Maschinenprofil)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="489"/>
        <source>; a changed profile applies at the next Connect</source>
        <translation>; ein geändertes Profil gilt ab dem nächsten Verbinden</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="544"/>
        <source>not seen yet</source>
        <translation>noch nicht empfangen</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="547"/>
        <source>%1 s ago</source>
        <translation>vor %1 s</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="555"/>
        <source>No plan: run a search or open a plan first.</source>
        <translation>Kein Plan: starten Sie zuerst eine Suche oder öffnen Sie einen Plan.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="556"/>
        <source>Plan with %n region(s).</source>
        <translation>
            <numerusform>Plan mit %n Bereich.</numerusform>
            <numerusform>Plan mit %n Bereichen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/device/hardware_panel.cpp" line="563"/>
        <source>all %n region(s) printed: finished</source>
        <translation>
            <numerusform>%n Bereich gedruckt: abgeschlossen</numerusform>
            <numerusform>alle %n Bereiche gedruckt: abgeschlossen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="565"/>
        <source>%1 of %2: %3</source>
        <translation>%1 von %2: %3</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="567"/>
        <source> (%1, %2)</source>
        <translation> (%1, %2)</translation>
    </message>
    <message>
        <location filename="../ui/device/hardware_panel.cpp" line="568"/>
        <source>; pausing after this region</source>
        <translation>; Pause nach diesem Bereich</translation>
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
        <location filename="../ui/main_window.cpp" line="65"/>
        <source>MultiDir Studio</source>
        <translation>MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="88"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="89"/>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="91"/>
        <source>Open a mesh file (STL, OBJ, OFF or PLY)</source>
        <translation>Eine Netzdatei öffnen (STL, OBJ, OFF oder PLY)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="93"/>
        <source>&amp;Samples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="102"/>
        <source>Open &amp;plan...</source>
        <translation>&amp;Plan öffnen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="104"/>
        <source>Show a plan saved earlier (a folder with plan.json)</source>
        <translation>Einen früher gespeicherten Plan anzeigen (ein Ordner mit plan.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="105"/>
        <source>&amp;Export plan...</source>
        <translation>Plan &amp;exportieren...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="107"/>
        <source>Save the plan shown: plan.json and one STL per region</source>
        <translation>Den angezeigten Plan speichern: plan.json und eine STL-Datei je Bereich</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="110"/>
        <source>&amp;Load machine profile...</source>
        <translation>Maschinenprofil &amp;laden...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="112"/>
        <source>&amp;Save machine profile...</source>
        <translation>Maschinenprofil &amp;speichern...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="115"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="118"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="119"/>
        <source>&amp;Fit to View</source>
        <translation>In Ansicht ein&amp;passen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="121"/>
        <source>Show the &amp;model (hide the plan)</source>
        <translation>&amp;Modell zeigen (Plan ausblenden)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="126"/>
        <source>&amp;Search</source>
        <translation>&amp;Suche</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="127"/>
        <source>&amp;Run</source>
        <translation>&amp;Starten</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="129"/>
        <source>&amp;Cancel</source>
        <translation>&amp;Abbrechen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="146"/>
        <source>Overhangs</source>
        <translation>Überhänge</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="147"/>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="148"/>
        <source>Search</source>
        <translation>Suche</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="149"/>
        <source>Plan</source>
        <translation>Plan</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="174"/>
        <source>Hardware</source>
        <translation>Hardware</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="187"/>
        <source>Printing direction</source>
        <translation>Druckrichtung</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="190"/>
        <source>Up:</source>
        <translation>Oben:</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="195"/>
        <source>The direction the model is printed along: the platform is below, overhangs are measured against it</source>
        <translation>Die Richtung, in der das Modell gedruckt wird: die Plattform liegt darunter, Überhänge werden daran gemessen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="200"/>
        <source>+X</source>
        <translation>+X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="200"/>
        <source>-X</source>
        <translation>-X</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="201"/>
        <source>+Y</source>
        <translation>+Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="201"/>
        <source>-Y</source>
        <translation>-Y</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="202"/>
        <source>+Z</source>
        <translation>+Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="202"/>
        <source>-Z</source>
        <translation>-Z</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="243"/>
        <source>Open Model</source>
        <translation>Modell öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="244"/>
        <source>Meshes (*.stl *.obj *.off *.ply);;All files (*)</source>
        <translation>Netze (*.stl *.obj *.off *.ply);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="260"/>
        <source>Custom (%1, %2, %3)</source>
        <translation>Benutzerdefiniert (%1, %2, %3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="281"/>
        <source>%1 - MultiDir Studio</source>
        <translation>%1 - MultiDir Studio</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="285"/>
        <source>Repaired on load: %1</source>
        <translation>Beim Laden repariert: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="299"/>
        <source>Could not open %1: %2</source>
        <translation>%1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="303"/>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="307"/>
        <source>%1 is still open.</source>
        <translation>%1 ist weiterhin geöffnet.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="326"/>
        <location filename="../ui/main_window.cpp" line="343"/>
        <source>No model</source>
        <translation>Kein Modell</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="336"/>
        <source>Triangles: %1</source>
        <translation>Dreiecke: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="337"/>
        <source>Volume: %1 mm³</source>
        <translation>Volumen: %1 mm³</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="351"/>
        <source>Risky area unavailable</source>
        <translation>Risikofläche nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="359"/>
        <source>Risky area (%1 up): %2 mm²</source>
        <translation>Risikofläche (%1 oben): %2 mm²</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="361"/>
        <source>Area of the faces that overhang by more than %1° for this up direction</source>
        <translation>Fläche der Dreiecke, die bei dieser Aufwärtsrichtung um mehr als %1° überhängen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="376"/>
        <location filename="../ui/main_window.cpp" line="395"/>
        <source>Open a model first.</source>
        <translation>Öffnen Sie zuerst ein Modell.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="378"/>
        <source>Fix the machine first: %1</source>
        <translation>Korrigieren Sie zuerst die Maschine: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="394"/>
        <source>A search is already running.</source>
        <translation>Eine Suche läuft bereits.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="400"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="404"/>
        <source>Cannot search: %1</source>
        <translation>Suche nicht möglich: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="405"/>
        <source>Cannot search.</source>
        <translation>Suche nicht möglich.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="419"/>
        <source>Searching %1...</source>
        <translation>Durchsuche %1...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="427"/>
        <source>Cancelling the search...</source>
        <translation>Suche wird abgebrochen...</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="435"/>
        <source>The search result was dropped: the model or its up direction changed.</source>
        <translation>Das Suchergebnis wurde verworfen: das Modell oder seine Aufwärtsrichtung hat sich geändert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="438"/>
        <source>Search cancelled: showing the best plan found so far.</source>
        <translation>Suche abgebrochen: der bisher beste Plan wird angezeigt.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="439"/>
        <source>Search finished.</source>
        <translation>Suche beendet.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="447"/>
        <source>Search failed: %1</source>
        <translation>Suche fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="474"/>
        <source>There is no plan to export: run a search first.</source>
        <translation>Es gibt keinen Plan zum Exportieren: starten Sie zuerst eine Suche.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="488"/>
        <source>Could not export the plan to %1: %2 (%3)</source>
        <translation>Der Plan konnte nicht nach %1 exportiert werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="491"/>
        <source>Plan exported to %1.</source>
        <translation>Plan nach %1 exportiert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="498"/>
        <source>Could not open the plan %1: %2 (%3)</source>
        <translation>Der Plan %1 konnte nicht geöffnet werden: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="543"/>
        <source>Machine profile saved to %1.</source>
        <translation>Maschinenprofil unter %1 gespeichert.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="555"/>
        <source>Machine profile %1 loaded.</source>
        <translation>Maschinenprofil %1 geladen.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="560"/>
        <source>Export Plan to Folder</source>
        <translation>Plan in Ordner exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="563"/>
        <source>Export Plan</source>
        <translation>Plan exportieren</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="567"/>
        <source>Open Plan Folder</source>
        <translation>Planordner öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="570"/>
        <source>Open Plan</source>
        <translation>Plan öffnen</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="574"/>
        <location filename="../ui/main_window.cpp" line="578"/>
        <source>Save Machine Profile</source>
        <translation>Maschinenprofil speichern</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="575"/>
        <source>Machine profiles (*.json)</source>
        <translation>Maschinenprofile (*.json)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="582"/>
        <location filename="../ui/main_window.cpp" line="586"/>
        <source>Load Machine Profile</source>
        <translation>Maschinenprofil laden</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="583"/>
        <source>Machine profiles (*.json);;All files (*)</source>
        <translation>Maschinenprofile (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="590"/>
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
