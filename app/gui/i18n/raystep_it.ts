<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="it" sourcelanguage="en">
<context>
    <name>raystep::gui::CompareWindow</name>
    <message>
        <location filename="../compare_window.cpp" line="34" />
        <source>raystep - compare midpoint, median and SAH</source>
        <translation>raystep - confronto tra midpoint, mediana e SAH</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="65" />
        <source>build ms</source>
        <translation>costruzione (ms)</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="65" />
        <source>nodes</source>
        <translation>nodi</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="65" />
        <source>leaves</source>
        <translation>foglie</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="65" />
        <source>max depth</source>
        <translation>profondità massima</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="66" />
        <source>references</source>
        <translation>riferimenti</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="66" />
        <source>SAH cost</source>
        <translation>costo SAH</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="66" />
        <source>ray: tests</source>
        <translation>raggio: test</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="66" />
        <source>ray: nodes visited</source>
        <translation>raggio: nodi visitati</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="67" />
        <source>ray: events</source>
        <translation>raggio: eventi</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="70" />
        <source>midpoint</source>
        <translation>midpoint</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="70" />
        <source>median</source>
        <translation>mediana</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="70" />
        <source>SAH</source>
        <translation>SAH</translation>
    </message>
    <message>
        <location filename="../compare_window.cpp" line="98" />
        <source>step (the same ray in each)</source>
        <translation>passo (lo stesso raggio in ognuno)</translation>
    </message>
</context>
<context>
    <name>raystep::gui::EventList</name>
    <message>
        <source>Filter events (e.g. cell, test, mailbox)</source>
        <translation>Filtra gli eventi (es. cell, test, mailbox)</translation>
    </message>
</context>
<context>
    <name>raystep::gui::ImageView</name>
    <message>
        <location filename="../image_view.cpp" line="85" />
        <source>Rendering...</source>
        <translation>Rendering in corso...</translation>
    </message>
    <message>
        <location filename="../image_view.cpp" line="85" />
        <source>The image view shows 3D scenes.</source>
        <translation>La vista immagine mostra le scene 3D.</translation>
    </message>
    <message>
        <location filename="../image_view.cpp" line="92" />
        <source>Primitive tests per pixel (dark: few, bright: many)</source>
        <translation>Test di primitive per pixel (scuro: pochi, chiaro: molti)</translation>
    </message>
    <message>
        <location filename="../image_view.cpp" line="93" />
        <source>Ray tracing (raystep): click a pixel to trace it</source>
        <translation>Ray tracing (raystep): clicca un pixel per tracciarlo</translation>
    </message>
</context>
<context>
    <name>raystep::gui::LessonController</name>
    <message>
        <source>Progress file unreadable, kept as %1: %2</source>
        <translation>File dei progressi illeggibile, conservato come %1: %2</translation>
    </message>
    <message>
        <source>Cannot save the progress to %1</source>
        <translation>Impossibile salvare i progressi in %1</translation>
    </message>
    <message>
        <source>Export progress report</source>
        <translation>Esporta il resoconto dei progressi</translation>
    </message>
    <message>
        <source>Markdown (*.md)</source>
        <translation>Markdown (*.md)</translation>
    </message>
    <message>
        <source>Tracing the same rays at %1 grid resolutions...</source>
        <translation>Tracciamento degli stessi raggi con %1 risoluzioni della griglia...</translation>
    </message>
    <message>
        <source>Cannot save</source>
        <translation>Impossibile salvare</translation>
    </message>
    <message>
        <source>Could not write %1</source>
        <translation>Impossibile scrivere %1</translation>
    </message>
</context>
<context>
    <name>raystep::gui::LessonPanel</name>
    <message>
        <location filename="../lesson_panel.cpp" line="27" />
        <source>Open a lesson</source>
        <translation>Apri una lezione</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="42" />
        <source>&lt; Step</source>
        <translation>&lt; Passo</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="43" />
        <source>Step &gt;</source>
        <translation>Passo &gt;</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="44" />
        <source>Previous step (Page Up)</source>
        <translation>Passo precedente (Pagina su)</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="45" />
        <source>Next step (Page Down)</source>
        <translation>Passo successivo (Pagina giù)</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="57" />
        <source>Exercise</source>
        <translation>Esercizio</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="83" />
        <source>Check</source>
        <translation>Verifica</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="84" />
        <source>Hint</source>
        <translation>Suggerimento</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="85" />
        <source>Show answer</source>
        <translation>Mostra la risposta</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="101" />
        <source>Run the sweep</source>
        <translation>Esegui lo sweep</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="113" />
        <source>Lessons...</source>
        <translation>Lezioni...</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="180" />
        <source>Step</source>
        <translation>Passo</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="184" />
        <source>Step %1 / %2</source>
        <translation>Passo %1 / %2</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="197" />
        <location filename="../lesson_panel.cpp" line="298" />
        <source>Exercise %1 / %2%3</source>
        <translation>Esercizio %1 / %2%3</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="200" />
        <location filename="../lesson_panel.cpp" line="301" />
        <source> (solved)</source>
        <translation> (risolto)</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="226" />
        <source>X,Y (or click the cell in the 2D view)</source>
        <translation>X,Y (o clicca la cella nella vista 2D)</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="229" />
        <source>a number, e.g. 1.25</source>
        <translation>un numero, ad es. 1,25</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="232" />
        <source>a whole number</source>
        <translation>un numero intero</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="235" />
        <source>hit T, or miss</source>
        <translation>hit T, oppure miss</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="235" />
        <source>hit or miss</source>
        <translation>hit oppure miss</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="278" />
        <source>Cannot read that answer: %1.</source>
        <translation>Risposta non leggibile: %1.</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="288" />
        <source>Right. %1</source>
        <translation>Giusto. %1</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="293" />
        <source>Not right. The answer is %1: %2</source>
        <translation>Non è giusto. La risposta è %1: %2</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="294" />
        <source>Not right yet (try %1 of 3). Step the replay and look at the inspector, or ask for a hint.</source>
        <translation>Non ancora giusto (tentativo %1 di 3). Fai avanzare la riproduzione e guarda l'ispettore, oppure chiedi un suggerimento.</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="308" />
        <source>Hint: %1</source>
        <translation>Suggerimento: %1</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="316" />
        <source>Answer: %1. %2</source>
        <translation>Risposta: %1. %2</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="321" />
        <source>cells/axis</source>
        <translation>celle/asse</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="322" />
        <source>cells</source>
        <translation>celle</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="322" />
        <source>refs</source>
        <translation>riferimenti</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="323" />
        <source>build ms</source>
        <translation>costruzione (ms)</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="321" />
        <source>tests/ray</source>
        <translation>test/raggio</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="321" />
        <source>cells/ray</source>
        <translation>celle/raggio</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="323" />
        <source>skips/ray</source>
        <translation>salti/raggio</translation>
    </message>
    <message>
        <location filename="../lesson_panel.cpp" line="322" />
        <source>trace ms</source>
        <translation>tracciamento (ms)</translation>
    </message>
</context>
<context>
    <name>raystep::gui::MainWindow</name>
    <message>
        <location filename="../main_window.cpp" line="115" />
        <source>raystep</source>
        <translation>raystep</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="181" />
        <source>Inspector</source>
        <translation>Ispettore</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="204" />
        <source>Events</source>
        <translation>Eventi</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="213" />
        <location filename="../main_window.cpp" line="406" />
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="223" />
        <source>Render cancelled</source>
        <translation>Rendering annullato</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="224" />
        <source>Rendered in %1 ms; click a pixel to trace it</source>
        <translation>Rendering in %1 ms; clicca un pixel per tracciarlo</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="230" />
        <source>Pixel (%1, %2): %3 events recorded</source>
        <translation>Pixel (%1, %2): %3 eventi registrati</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="271" />
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="272" />
        <source>&amp;Open scene...</source>
        <translation>&amp;Apri scena...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="273" />
        <source>Export &amp;trace...</source>
        <translation>Esporta &amp;traccia...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="274" />
        <source>Export screenshot of the &amp;window...</source>
        <translation>Esporta screenshot della &amp;finestra...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="275" />
        <source>window</source>
        <translation>finestra</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="276" />
        <source>Export screenshot of the &amp;2D view...</source>
        <translation>Esporta screenshot della vista &amp;2D...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="277" />
        <source>2D view</source>
        <translation>vista 2D</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="278" />
        <source>Export screenshot of the &amp;3D view...</source>
        <translation>Esporta screenshot della vista &amp;3D...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="279" />
        <source>3D view</source>
        <translation>vista 3D</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="280" />
        <source>Export screenshot of the &amp;image view...</source>
        <translation>Esporta screenshot della vista &amp;immagine...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="281" />
        <source>image view</source>
        <translation>vista immagine</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="282" />
        <source>Export &amp;progress report...</source>
        <translation>Esporta il resoconto dei &amp;progressi...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="284" />
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="285" />
        <source>&amp;Replay</source>
        <translation>&amp;Riproduzione</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="286" />
        <source>Step &amp;forward</source>
        <translation>Passo &amp;avanti</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="288" />
        <source>Step &amp;back</source>
        <translation>Passo &amp;indietro</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="289" />
        <source>&amp;Play / pause</source>
        <translation>A&amp;vvia / pausa</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="291" />
        <source>&amp;Next event of the kind</source>
        <translation>&amp;Prossimo evento del tipo</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="294" />
        <source>Replay the &amp;build (candidates, splits, leaves)</source>
        <translation>Riproduci la &amp;costruzione (candidati, split, foglie)</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="296" />
        <source>Replay the &amp;example ray</source>
        <translation>Riproduci il raggio d'&amp;esempio</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="299" />
        <source>&amp;First event</source>
        <translation>P&amp;rimo evento</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="301" />
        <source>&amp;Last event</source>
        <translation>&amp;Ultimo evento</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="303" />
        <source>&amp;Lessons</source>
        <translation>&amp;Lezioni</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="304" />
        <source>&amp;Built-in lessons</source>
        <translation>Lezioni &amp;incluse</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="306" />
        <source>Open lesson &amp;file...</source>
        <translation>Apri &amp;file di lezione...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="307" />
        <source>Open lesson</source>
        <translation>Apri lezione</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="308" />
        <source>Lessons (*.json)</source>
        <translation>Lezioni (*.json)</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="311" />
        <source>&amp;Lecturer mode (show answers)</source>
        <translation>Modalità &amp;docente (mostra le risposte)</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="315" />
        <source>&amp;View</source>
        <translation>&amp;Vista</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="316" />
        <source>&amp;Compare midpoint, median and SAH...</source>
        <translation>&amp;Confronta midpoint, mediana e SAH...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="318" />
        <source>&amp;Heat map of primitive tests</source>
        <translation>&amp;Mappa di calore dei test di primitive</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="321" />
        <source>&amp;Reset 3D camera</source>
        <translation>&amp;Reimposta la camera 3D</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="329" />
        <source>Loading %1 and building its %2...</source>
        <translation>Caricamento di %1 e costruzione del suo %2...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="341" />
        <source>Opening %1 cancelled</source>
        <translation>Apertura di %1 annullata</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="346" />
        <source>Cannot open the scene</source>
        <translation>Impossibile aprire la scena</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="368" />
        <source>Rendering %1...</source>
        <translation>Rendering di %1...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="379" />
        <source>raystep - %1</source>
        <translation>raystep - %1</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="426" />
        <location filename="../main_window.cpp" line="440" />
        <source>Cannot open the lesson</source>
        <translation>Impossibile aprire la lezione</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="450" />
        <source>raystep - lesson %1: %2</source>
        <translation>raystep - lezione %1: %2</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="553" />
        <source>Building the midpoint, median and SAH trees...</source>
        <translation>Costruzione degli alberi midpoint, mediana e SAH...</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="560" />
        <source>Compare cancelled</source>
        <translation>Confronto annullato</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="562" />
        <source>Compare</source>
        <translation>Confronto</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="622" />
        <source>Open scene</source>
        <translation>Apri scena</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="622" />
        <source>Scenes (*.json)</source>
        <translation>Scene (*.json)</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="627" />
        <source>Screenshot of the %1</source>
        <translation>Screenshot della %1</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="628" />
        <source>PNG images (*.png)</source>
        <translation>Immagini PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="498" />
        <location filename="../main_window.cpp" line="631" />
        <location filename="../main_window.cpp" line="645" />
        <source>Cannot save</source>
        <translation>Impossibile salvare</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="635" />
        <source>Export trace</source>
        <translation>Esporta traccia</translation>
    </message>
    <message>
        <location filename="../main_window.cpp" line="636" />
        <source>Trace files (*.json)</source>
        <translation>File di traccia (*.json)</translation>
    </message>
</context>
<context>
    <name>raystep::gui::Timeline</name>
    <message>
        <source>DDA step</source>
        <translation>passo del DDA</translation>
    </message>
    <message>
        <source>primitive test</source>
        <translation>test di una primitiva</translation>
    </message>
    <message>
        <source>mailbox skip</source>
        <translation>saltata dalla mailbox</translation>
    </message>
    <message>
        <source>node enter</source>
        <translation>ingresso in un nodo</translation>
    </message>
    <message>
        <source>ray begin</source>
        <translation>inizio di un raggio</translation>
    </message>
    <message>
        <source>hit</source>
        <translation>intersezione</translation>
    </message>
    <message>
        <source>split chosen</source>
        <translation>split scelto</translation>
    </message>
    <message>
        <source>First event (Home)</source>
        <translation>Primo evento (Home)</translation>
    </message>
    <message>
        <source>Step back (Left)</source>
        <translation>Passo indietro (Sinistra)</translation>
    </message>
    <message>
        <source>Play / pause (Space)</source>
        <translation>Avvia / pausa (Spazio)</translation>
    </message>
    <message>
        <source>Step forward (Right)</source>
        <translation>Passo avanti (Destra)</translation>
    </message>
    <message>
        <source>next</source>
        <translation>successivo</translation>
    </message>
    <message>
        <source>Jump to the next event of this kind (N)</source>
        <translation>Salta al prossimo evento di questo tipo (N)</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>velocità</translation>
    </message>
    <message>
        <source> /s</source>
        <translation> /s</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
</context>
<context>
    <name>raystep::gui::View2D</name>
    <message>
        <location filename="../view2d.cpp" line="128" />
        <source>The 2D view shows the lecture's 2D scenes.</source>
        <translation>La vista 2D mostra le scene 2D della lezione.</translation>
    </message>
    <message>
        <location filename="../view2d.cpp" line="401" />
        <source>SAH cost of each candidate (X blue, Y purple; dashed: leaf)</source>
        <translation>Costo SAH di ogni candidato (X blu, Y viola; tratteggio: foglia)</translation>
    </message>
</context>
<context>
    <name>raystep::gui::VtkView</name>
    <message>
        <location filename="../vtk_view.cpp" line="299" />
        <source>The 3D view shows 3D scenes.</source>
        <translation>La vista 3D mostra le scene 3D.</translation>
    </message>
    <message>
        <location filename="../vtk_view.cpp" line="313" />
        <source>Rasterization (VTK, OpenGL): the scene and the recorded rays</source>
        <translation>Rasterizzazione (VTK, OpenGL): la scena e i raggi registrati</translation>
    </message>
</context>
</TS>