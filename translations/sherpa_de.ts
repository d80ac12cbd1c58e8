<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>Format</name>
    <message>
        <source>%1 B</source>
        <translation>%1 B</translation>
    </message>
    <message>
        <source>%1 KiB</source>
        <translation>%1 KiB</translation>
    </message>
    <message>
        <source>%1 MiB</source>
        <translation>%1 MiB</translation>
    </message>
    <message>
        <source>unknown (%1)</source>
        <translation>unbekannt (%1)</translation>
    </message>
    <message>
        <source>authored</source>
        <translation>aus der Datei</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>erzeugt</translation>
    </message>
    <message>
        <source>defaulted</source>
        <translation>Standardwert</translation>
    </message>
    <message>
        <source>colour (sRGB)</source>
        <translation>Farbe (sRGB)</translation>
    </message>
    <message>
        <source>linear data</source>
        <translation>lineare Daten</translation>
    </message>
    <message>
        <source>normal map</source>
        <translation>Normal-Map</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>unbenutzt</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
</context>
<context>
    <name>LabChart</name>
    <message>
        <source>time (%1)</source>
        <translation>Zeit (%1)</translation>
    </message>
    <message>
        <source>Pareto front</source>
        <translation>Pareto-Front</translation>
    </message>
    <message>
        <source>%1 (in use)</source>
        <translation>%1 (in Verwendung)</translation>
    </message>
</context>
<context>
    <name>ViewCatalog</name>
    <message>
        <source>Lit</source>
        <translation>Beleuchtet</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <source>Tangents</source>
        <translation>Tangenten</translation>
    </message>
    <message>
        <source>Bitangents</source>
        <translation>Bitangenten</translation>
    </message>
    <message>
        <source>Handedness (tangent w)</source>
        <translation>Händigkeit (Tangente w)</translation>
    </message>
    <message>
        <source>UV 0</source>
        <translation>UV 0</translation>
    </message>
    <message>
        <source>UV 1</source>
        <translation>UV 1</translation>
    </message>
    <message>
        <source>UV 0 checker</source>
        <translation>UV-0-Schachbrett</translation>
    </message>
    <message>
        <source>UV 1 checker</source>
        <translation>UV-1-Schachbrett</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>Grundfarbe</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Metallisch</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Rauheit</translation>
    </message>
    <message>
        <source>Occlusion</source>
        <translation>Verdeckung</translation>
    </message>
    <message>
        <source>Emissive</source>
        <translation>Emission</translation>
    </message>
    <message>
        <source>Geometric vs shading normal</source>
        <translation>Geometrie- vs. Shading-Normale</translation>
    </message>
    <message>
        <source>Tangent provenance</source>
        <translation>Herkunft der Tangenten</translation>
    </message>
    <message>
        <source>Shading normal</source>
        <translation>Shading-Normale</translation>
    </message>
    <message>
        <source>Specular (F0)</source>
        <translation>Spiegelnd (F0)</translation>
    </message>
    <message>
        <source>Joint influence</source>
        <translation>Gelenkeinfluss</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>Drahtgitter</translation>
    </message>
    <message>
        <source>Normal glyphs</source>
        <translation>Normalen-Glyphen</translation>
    </message>
    <message>
        <source>Tangent glyphs</source>
        <translation>Tangenten-Glyphen</translation>
    </message>
    <message>
        <source>Bitangent glyphs</source>
        <translation>Bitangenten-Glyphen</translation>
    </message>
    <message>
        <source>Bounding boxes</source>
        <translation>Hüllquader</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>Sun shadow</source>
        <translation>Sonnenschatten</translation>
    </message>
    <message>
        <source>Ambient occlusion (rays)</source>
        <translation>Umgebungsverdeckung (Strahlen)</translation>
    </message>
    <message>
        <source>Shadow error (maps vs rays)</source>
        <translation>Schattenfehler (Maps gegen Strahlen)</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>Brechungsindex</translation>
    </message>
    <message>
        <source>Specular weight</source>
        <translation>Spiegelnde Stärke</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>Spiegelnde Farbe</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>Transmission</translation>
    </message>
    <message>
        <source>Volume thickness</source>
        <translation>Volumendicke</translation>
    </message>
    <message>
        <source>Volume attenuation</source>
        <translation>Volumendämpfung</translation>
    </message>
    <message>
        <source>Diffuse transmission</source>
        <translation>Diffuse Transmission</translation>
    </message>
    <message>
        <source>Clearcoat</source>
        <translation>Klarlack</translation>
    </message>
    <message>
        <source>Clearcoat roughness</source>
        <translation>Klarlack-Rauheit</translation>
    </message>
    <message>
        <source>Clearcoat normal</source>
        <translation>Klarlack-Normale</translation>
    </message>
    <message>
        <source>Sheen colour</source>
        <translation>Sheen-Farbe</translation>
    </message>
    <message>
        <source>Sheen roughness</source>
        <translation>Sheen-Rauheit</translation>
    </message>
    <message>
        <source>Anisotropy strength</source>
        <translation>Anisotropie-Stärke</translation>
    </message>
    <message>
        <source>Anisotropy direction</source>
        <translation>Anisotropie-Richtung</translation>
    </message>
    <message>
        <source>Iridescence</source>
        <translation>Irisieren</translation>
    </message>
    <message>
        <source>Iridescence thickness</source>
        <translation>Irisieren-Schichtdicke</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AccelerationDock</name>
    <message>
        <source>Acceleration Structures</source>
        <translation>Beschleunigungsstrukturen</translation>
    </message>
    <message>
        <source>%1 BLAS, %2 triangles, %3 built, %4 compacted (%5%), %6 batches, built in %7 ms</source>
        <translation>%1 BLAS, %2 Dreiecke, %3 gebaut, %4 kompaktiert (%5%), %6 Stapel, gebaut in %7 ms</translation>
    </message>
    <message>
        <source>TLAS: %1 instances of %2 node/mesh pairs, %3 deduplicated, %4 mirrored, %5 hidden, %6 non-finite; %7</source>
        <translation>TLAS: %1 Instanzen aus %2 Knoten/Mesh-Paaren, %3 dedupliziert, %4 gespiegelt, %5 ausgeblendet, %6 nicht endlich; %7</translation>
    </message>
    <message>
        <source>Total on the GPU: %1 (scratch buffer %2)</source>
        <translation>Gesamt auf der GPU: %1 (Scratch-Puffer %2)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AccelerationModel</name>
    <message>
        <source>%1 geometries (one per triangle primitive), %2 of them opaque (no any-hit)</source>
        <translation>%1 Geometrien (eine je Dreiecksprimitiv), davon %2 opak (kein Any-Hit)</translation>
    </message>
    <message>
        <source>mesh %1</source>
        <translation>Mesh %1</translation>
    </message>
    <message>
        <source>Geometries (opaque)</source>
        <translation>Geometrien (opak)</translation>
    </message>
    <message>
        <source>Mesh</source>
        <translation>Mesh</translation>
    </message>
    <message>
        <source>Geometries</source>
        <translation>Geometrien</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>Build ms</source>
        <translation>Bau ms</translation>
    </message>
    <message>
        <source>Built</source>
        <translation>Gebaut</translation>
    </message>
    <message>
        <source>Compacted</source>
        <translation>Kompaktiert</translation>
    </message>
    <message>
        <source>Scratch</source>
        <translation>Scratch</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AttributeModel</name>
    <message>
        <source>indices</source>
        <translation>Indizes</translation>
    </message>
    <message>
        <source>authored</source>
        <translation>aus der Datei</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>erzeugt</translation>
    </message>
    <message>
        <source>not uploaded</source>
        <translation>nicht hochgeladen</translation>
    </message>
    <message>
        <source>yes (%1 values)</source>
        <translation>ja (%1 Werte)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 (stride %2)</source>
        <translation>%1 (Schrittweite %2)</translation>
    </message>
    <message>
        <source>Attribute</source>
        <translation>Attribut</translation>
    </message>
    <message>
        <source>Provenance</source>
        <translation>Herkunft</translation>
    </message>
    <message>
        <source>Accessor</source>
        <translation>Accessor</translation>
    </message>
    <message>
        <source>Normalized</source>
        <translation>Normalisiert</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Sparse</source>
        <translation>Sparse</translation>
    </message>
    <message>
        <source>Buffer view</source>
        <translation>Buffer-View</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU-Bytes</translation>
    </message>
    <message>
        <source>, normalized</source>
        <translation>, normalisiert</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>Komponente</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CommandLine</name>
    <message>
        <source>First frame of the scene %1 ms after launch.</source>
        <translation>Erstes Bild der Szene %1 ms nach dem Start.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CompareController</name>
    <message>
        <source>Compare with glTF scene</source>
        <translation>Mit glTF-Szene vergleichen</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb);;All files (*)</source>
        <translation>glTF-Szenen (*.gltf *.glb);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Side B: %1 could not be loaded: %2</source>
        <translation>Seite B: %1 konnte nicht geladen werden: %2</translation>
    </message>
    <message>
        <source>Side B: %1 loaded.</source>
        <translation>Seite B: %1 geladen.</translation>
    </message>
    <message>
        <source>Side B: loading %1…</source>
        <translation>Seite B: %1 wird geladen…</translation>
    </message>
    <message>
        <source>%1, source textures</source>
        <translation>%1, Quelltexturen</translation>
    </message>
    <message>
        <source>Side B: loading %1 with tangents by %2…</source>
        <translation>Seite B: %1 wird mit Tangenten nach %2 geladen…</translation>
    </message>
    <message>
        <source>%1, tangents: %2</source>
        <translation>%1, Tangenten: %2</translation>
    </message>
    <message>
        <source>Side A&apos;s tangents: %1 primitive(s) authored, %2 exact MikkTSpace, %3 none (no TANGENT, no normal texture: there B differs from no tangents).</source>
        <translation>Tangenten von Seite A: %1 Primitiv(e) aus der Datei, %2 exaktes MikkTSpace, %3 keine (kein TANGENT, keine Normal-Textur: dort unterscheidet sich B von fehlenden Tangenten).</translation>
    </message>
    <message>
        <source>Overlays and the selection highlight are drawn in the Raster mode only.</source>
        <translation>Overlays und die Auswahlhervorhebung werden nur im Rastermodus gezeichnet.</translation>
    </message>
    <message>
        <source>The ray tracer cannot draw this frame: %1. Back to Raster.</source>
        <translation>Der Raytracer kann dieses Bild nicht zeichnen: %1. Zurück zur Rasterisierung.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CompareControls</name>
    <message>
        <source>Raster</source>
        <translation>Rasterisierung</translation>
    </message>
    <message>
        <source>Ray traced</source>
        <translation>Raytracing</translation>
    </message>
    <message>
        <source>Split (A | B)</source>
        <translation>Geteilt (A | B)</translation>
    </message>
    <message>
        <source>Difference (heat map)</source>
        <translation>Differenz (Heatmap)</translation>
    </message>
    <message>
        <source>Viewport &amp;Mode</source>
        <translation>Darstellungs&amp;modus</translation>
    </message>
    <message>
        <source>Compare &amp;With (side B)</source>
        <translation>&amp;Vergleichen mit (Seite B)</translation>
    </message>
    <message>
        <source>Another Debug View</source>
        <translation>Andere Debug-Ansicht</translation>
    </message>
    <message>
        <source>The Ray Tracer</source>
        <translation>Der Raytracer</translation>
    </message>
    <message>
        <source>Another File…</source>
        <translation>Andere Datei…</translation>
    </message>
    <message>
        <source>Another File… (%1)</source>
        <translation>Andere Datei… (%1)</translation>
    </message>
    <message>
        <source>Viewport: %1</source>
        <translation>Darstellung: %1</translation>
    </message>
    <message>
        <source>Raster or ray traced frame, or side A (this view, rasterized) against side B with one camera. Split: drag the divider line (or Ctrl+drag anywhere) to move it.</source>
        <translation>Rasterisiertes oder per Raytracing berechnetes Bild, oder Seite A (diese Ansicht, rasterisiert) gegen Seite B mit einer Kamera. Geteilt: die Trennlinie ziehen (oder Strg+Ziehen an beliebiger Stelle), um sie zu verschieben.</translation>
    </message>
    <message>
        <source>ray tracer</source>
        <translation>Raytracer</translation>
    </message>
    <message>
        <source>no file</source>
        <translation>keine Datei</translation>
    </message>
    <message>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <source>This File, Source Textures (no BC7/BC5)</source>
        <translation>Diese Datei, Quelltexturen (ohne BC7/BC5)</translation>
    </message>
    <message>
        <source>The rasterizer: every view, overlays and the selection</source>
        <translation>Der Rasterisierer: jede Ansicht, Overlays und die Auswahl</translation>
    </message>
    <message>
        <source>Primary rays through the acceleration structures: the surface-data views</source>
        <translation>Primärstrahlen durch die Beschleunigungsstrukturen: die Oberflächendaten-Ansichten</translation>
    </message>
    <message>
        <source>Side A left, side B right, one camera: drag the divider line (or Ctrl+drag anywhere) to move it</source>
        <translation>Seite A links, Seite B rechts, eine Kamera: die Trennlinie ziehen (oder Strg+Ziehen an beliebiger Stelle), um sie zu verschieben</translation>
    </message>
    <message>
        <source>Heat map of |A − B| with its legend: mean, max, PSNR, % of pixels over the threshold</source>
        <translation>Heatmap von |A − B| mit Legende: Mittel, Maximum, PSNR, % der Pixel über dem Schwellwert</translation>
    </message>
    <message>
        <source>Difference &amp;Heat Scale</source>
        <translation>&amp;Heatmap-Skala der Differenz</translation>
    </message>
    <message>
        <source>Difference &amp;Threshold</source>
        <translation>&amp;Schwellwert der Differenz</translation>
    </message>
    <message>
        <source>%1/255 and above at full heat</source>
        <translation>%1/255 und mehr in voller Hitze</translation>
    </message>
    <message>
        <source>Automatic (99.9th percentile of the differences)</source>
        <translation>Automatisch (99,9. Perzentil der Differenzen)</translation>
    </message>
    <message>
        <source>Over %1/255</source>
        <translation>Über %1/255</translation>
    </message>
    <message>
        <source>MikkTSpace, exact (vertices split per corner)</source>
        <translation>MikkTSpace, exakt (Vertices je Ecke aufgeteilt)</translation>
    </message>
    <message>
        <source>MikkTSpace, welded (last corner per vertex)</source>
        <translation>MikkTSpace, verschweißt (letzte Ecke je Vertex)</translation>
    </message>
    <message>
        <source>Lengyel (summed per vertex)</source>
        <translation>Lengyel (je Vertex summiert)</translation>
    </message>
    <message>
        <source>This File, Tangents Regenerated By</source>
        <translation>Diese Datei, Tangenten neu erzeugt mit</translation>
    </message>
    <message>
        <source>What side B of the comparison draws: %1</source>
        <translation>Was Seite B des Vergleichs zeichnet: %1</translation>
    </message>
    <message>
        <source>Side B is shown in the Split and Difference modes (Viewport button); choosing it here switches to Split. Now: %1</source>
        <translation>Seite B erscheint in den Modi Geteilt und Differenz (Schaltfläche Darstellung); eine Wahl hier schaltet auf Geteilt. Jetzt: %1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CullingDock</name>
    <message>
        <source>Culling Statistics</source>
        <translation>Culling-Statistik</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Sichtbar</translation>
    </message>
    <message>
        <source>Culled</source>
        <translation>Verworfen</translation>
    </message>
    <message>
        <source>False positives</source>
        <translation>Falsch positiv</translation>
    </message>
    <message>
        <source>Draw calls</source>
        <translation>Draw-Calls</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>CPU cull ms</source>
        <translation>CPU-Culling ms</translation>
    </message>
    <message>
        <source>GPU cull ms</source>
        <translation>GPU-Culling ms</translation>
    </message>
    <message>
        <source>Hidden</source>
        <translation>Ausgeblendet</translation>
    </message>
    <message>
        <source>visible</source>
        <translation>sichtbar</translation>
    </message>
    <message>
        <source>culled</source>
        <translation>verworfen</translation>
    </message>
    <message>
        <source>update</source>
        <translation>Aktualisierung</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>Keine Szene.</translation>
    </message>
    <message>
        <source>Pass &quot;%1&quot;: method %2, %3%4</source>
        <translation>Durchgang „%1“: Methode %2, %3%4</translation>
    </message>
    <message>
        <source>, culling camera frozen</source>
        <translation>, Culling-Kamera eingefroren</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: GPU path off (Culling › Path › GPU)</source>
        <translation>CPU/GPU-Übereinstimmung: GPU-Pfad aus (Culling › Pfad › GPU)</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: ✔ both keep %1 of %2</source>
        <translation>CPU/GPU-Übereinstimmung: ✔ beide behalten %1 von %2</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: ✘ %1 objects differ (CPU keeps %2, GPU %3)</source>
        <translation>CPU/GPU-Übereinstimmung: ✘ %1 Objekte weichen ab (CPU behält %2, GPU %3)</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Durchlauf</translation>
    </message>
    <message>
        <source>Renderer passes: none (culling off or no frame yet)</source>
        <translation>Renderer-Durchläufe: keine (Culling aus oder noch kein Bild)</translation>
    </message>
    <message>
        <source>Renderer passes, last frame (cascades reused from the frame that drew them)</source>
        <translation>Renderer-Durchläufe, letztes Bild (Kaskaden aus dem Bild übernommen, das sie gezeichnet hat)</translation>
    </message>
    <message>
        <source>Renderer passes, last frame</source>
        <translation>Renderer-Durchläufe, letztes Bild</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::DifferenceLegend</name>
    <message>
        <source>|A − B|, largest of R, G, B (of 255)</source>
        <translation>|A − B|, größter Wert von R, G, B (von 255)</translation>
    </message>
    <message>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <source>No frame compared yet.</source>
        <translation>Noch kein Bild verglichen.</translation>
    </message>
    <message>
        <source>∞ (identical)</source>
        <translation>∞ (identisch)</translation>
    </message>
    <message>
        <source>%1 dB</source>
        <translation>%1 dB</translation>
    </message>
    <message>
        <source>mean %1
max %2
PSNR %3
%4% of %5 pixels over %6</source>
        <translation>Mittel %1
Max. %2
PSNR %3
%4% von %5 Pixeln über %6</translation>
    </message>
    <message>
        <source>≥ %1 (auto)</source>
        <translation>≥ %1 (automatisch)</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>automatisch</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::EnvironmentMenu</name>
    <message>
        <source>&amp;Environment</source>
        <translation>&amp;Umgebung</translation>
    </message>
    <message>
        <source>&amp;None (Ambient Only)</source>
        <translation>&amp;Keine (nur Umgebungslicht-Term)</translation>
    </message>
    <message>
        <source>&amp;Room (Built In)</source>
        <translation>&amp;Raum (eingebaut)</translation>
    </message>
    <message>
        <source>&amp;Open HDR or EXR… (%1)</source>
        <translation>HDR oder EXR ö&amp;ffnen… (%1)</translation>
    </message>
    <message>
        <source>&amp;Open HDR or EXR…</source>
        <translation>HDR oder EXR ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Background</source>
        <translation>&amp;Hintergrund</translation>
    </message>
    <message>
        <source>&amp;Blurred</source>
        <translation>&amp;Weichgezeichnet</translation>
    </message>
    <message>
        <source>&amp;Solid Colour</source>
        <translation>&amp;Einfarbig</translation>
    </message>
    <message>
        <source>Rotate −15° (now %1°)</source>
        <translation>Um −15° drehen (jetzt %1°)</translation>
    </message>
    <message>
        <source>Rotate +15° (now %1°)</source>
        <translation>Um +15° drehen (jetzt %1°)</translation>
    </message>
    <message>
        <source>Brighter (intensity %1)</source>
        <translation>Heller (Intensität %1)</translation>
    </message>
    <message>
        <source>Darker</source>
        <translation>Dunkler</translation>
    </message>
    <message>
        <source>Reset Rotation and Intensity</source>
        <translation>Drehung und Intensität zurücksetzen</translation>
    </message>
    <message>
        <source>Default &amp;Sun</source>
        <translation>Standard-&amp;Sonne</translation>
    </message>
    <message>
        <source>Energy &amp;Compensation (Multiple Scattering)</source>
        <translation>Energie&amp;kompensation (Mehrfachstreuung)</translation>
    </message>
    <message>
        <source>&amp;Tone Mapping</source>
        <translation>&amp;Tone-Mapping</translation>
    </message>
    <message>
        <source>Khronos PBR &amp;Neutral</source>
        <translation>Khronos PBR &amp;Neutral</translation>
    </message>
    <message>
        <source>&amp;ACES Filmic</source>
        <translation>&amp;ACES Filmic</translation>
    </message>
    <message>
        <source>A&amp;gX</source>
        <translation>A&amp;gX</translation>
    </message>
    <message>
        <source>&amp;Linear (Clamp)</source>
        <translation>&amp;Linear (Begrenzen)</translation>
    </message>
    <message>
        <source>Exposure +½ Stop (now %1 EV)</source>
        <translation>Belichtung +½ Blende (jetzt %1 EV)</translation>
    </message>
    <message>
        <source>Exposure −½ Stop</source>
        <translation>Belichtung −½ Blende</translation>
    </message>
    <message>
        <source>Exposure 0 EV</source>
        <translation>Belichtung 0 EV</translation>
    </message>
    <message>
        <source>Open Environment</source>
        <translation>Umgebung öffnen</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>HDR-Bilder (*.hdr *.exr);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::InstanceTableModel</name>
    <message>
        <source>Row</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>T.x</source>
        <translation>T.x</translation>
    </message>
    <message>
        <source>T.y</source>
        <translation>T.y</translation>
    </message>
    <message>
        <source>T.z</source>
        <translation>T.z</translation>
    </message>
    <message>
        <source>R.x</source>
        <translation>R.x</translation>
    </message>
    <message>
        <source>R.y</source>
        <translation>R.y</translation>
    </message>
    <message>
        <source>R.z</source>
        <translation>R.z</translation>
    </message>
    <message>
        <source>R.w</source>
        <translation>R.w</translation>
    </message>
    <message>
        <source>S.x</source>
        <translation>S.x</translation>
    </message>
    <message>
        <source>S.y</source>
        <translation>S.y</translation>
    </message>
    <message>
        <source>S.z</source>
        <translation>S.z</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LabDock</name>
    <message>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>The Lab could not run: %1</source>
        <translation>Das Labor konnte nicht laufen: %1</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>SVG (*.svg)</source>
        <translation>SVG (*.svg)</translation>
    </message>
    <message>
        <source>PNG (*.png)</source>
        <translation>PNG (*.png)</translation>
    </message>
    <message>
        <source>Lab</source>
        <translation>Labor</translation>
    </message>
    <message>
        <source>Methods</source>
        <translation>Methoden</translation>
    </message>
    <message>
        <source>Budget</source>
        <translation>Budget</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Compute budget</source>
        <translation>Budget berechnen</translation>
    </message>
    <message>
        <source>Numbers</source>
        <translation>Zahlen</translation>
    </message>
    <message>
        <source>Failures</source>
        <translation>Fehlschläge</translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <source>SVG…</source>
        <translation>SVG…</translation>
    </message>
    <message>
        <source>PNG…</source>
        <translation>PNG…</translation>
    </message>
    <message>
        <source>The family of methods to measure on the loaded scene</source>
        <translation>Die Methodenfamilie, die an der geladenen Szene gemessen wird</translation>
    </message>
    <message>
        <source>Measure every method of the family on this scene, off the UI thread</source>
        <translation>Jede Methode der Familie an dieser Szene messen, außerhalb des UI-Threads</translation>
    </message>
    <message>
        <source>The numbers, as sherpa-cli lab --csv writes them</source>
        <translation>Die Zahlen, wie sherpa-cli lab --csv sie schreibt</translation>
    </message>
    <message>
        <source>The chart, as sherpa-cli lab --chart writes it</source>
        <translation>Das Diagramm, wie sherpa-cli lab --chart es schreibt</translation>
    </message>
    <message>
        <source>The chart as shown</source>
        <translation>Das Diagramm wie angezeigt</translation>
    </message>
    <message>
        <source>Pick a family and run it on %1.</source>
        <translation>Eine Familie wählen und auf %1 ausführen.</translation>
    </message>
    <message>
        <source>Open a scene to measure its methods.</source>
        <translation>Eine Szene öffnen, um ihre Methoden zu messen.</translation>
    </message>
    <message>
        <source>Compute the budget of %1.</source>
        <translation>Das Budget von %1 berechnen.</translation>
    </message>
    <message>
        <source>Open a scene to compute its budget.</source>
        <translation>Eine Szene öffnen, um ihr Budget zu berechnen.</translation>
    </message>
    <message>
        <source>Running %1 on %2…</source>
        <translation>%1 läuft auf %2…</translation>
    </message>
    <message>
        <source>Computing the budget of %1…</source>
        <translation>Budget von %1 wird berechnet…</translation>
    </message>
    <message>
        <source>%1 against %2; time in %3</source>
        <translation>%1 gegen %2; Zeit in %3</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Export the Lab report</source>
        <translation>Laborbericht exportieren</translation>
    </message>
    <message>
        <source>The line joins the Pareto front; the method in use is ringed.</source>
        <translation>Die Linie verbindet die Pareto-Front; die verwendete Methode ist umringt.</translation>
    </message>
    <message>
        <source>Click a point (or double-click a row) to use that method in the viewport: culling methods, and the cascade count and PCF taps of a shadow setting (the viewport&apos;s shadow maps keep their resolution, fixed when its renderer is made). Tangent and texture methods are measured here but the viewport has no switch for them, so clicking them changes nothing.</source>
        <translation>Einen Punkt anklicken (oder eine Zeile doppelklicken), um diese Methode im Viewport zu verwenden: Culling-Methoden sowie Kaskadenzahl und PCF-Abtastungen einer Schatteneinstellung (die Schattenmaps des Viewports behalten ihre Auflösung, die beim Erzeugen seines Renderers festgelegt wird). Tangenten- und Texturmethoden werden hier gemessen, aber der Viewport hat keinen Schalter dafür; ein Klick ändert dort nichts.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LabTableModel</name>
    <message>
        <source>Method</source>
        <translation>Methode</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Time (%1)</source>
        <translation>Zeit (%1)</translation>
    </message>
    <message>
        <source>Failures</source>
        <translation>Fehlschläge</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>nicht gelaufen</translation>
    </message>
    <message>
        <source>Cause</source>
        <translation>Ursache</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Wo</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU-Bytes</translation>
    </message>
    <message>
        <source>Unified</source>
        <translation>Einheitlich</translation>
    </message>
    <message>
        <source>Stored</source>
        <translation>Gespeichert</translation>
    </message>
    <message>
        <source>Needed</source>
        <translation>Benötigt</translation>
    </message>
    <message>
        <source>Oversized texture</source>
        <translation>Übergroße Textur</translation>
    </message>
    <message>
        <source>%1×%2: %3 texels per pixel at best, 1/%4 per side would look the same</source>
        <translation>%1×%2: bestenfalls %3 Texel pro Pixel, 1/%4 pro Seite sähe gleich aus</translation>
    </message>
    <message>
        <source>Unread attribute</source>
        <translation>Ungelesenes Attribut</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>Befund</translation>
    </message>
    <message>
        <source>Detail</source>
        <translation>Detail</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LoadController</name>
    <message>
        <source>Loading %1 cancelled; the result is discarded.</source>
        <translation>Laden von %1 abgebrochen; das Ergebnis wird verworfen.</translation>
    </message>
    <message>
        <source>Texture cache directory</source>
        <translation>Verzeichnis des Textur-Caches</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>Lade %1 …</translation>
    </message>
    <message>
        <source>1/4 parsing…</source>
        <translation>1/4 Einlesen…</translation>
    </message>
    <message>
        <source>2/4 geometry…</source>
        <translation>2/4 Geometrie…</translation>
    </message>
    <message>
        <source>3/4 tangents: mesh %1 of %2</source>
        <translation>3/4 Tangenten: Mesh %1 von %2</translation>
    </message>
    <message>
        <source>4/4 textures: %1 of %2</source>
        <translation>4/4 Texturen: %1 von %2</translation>
    </message>
    <message>
        <source>Loaded %1 in %2 ms (engine %3 ms, thumbnails %4 ms, textures %5 ms).</source>
        <translation>%1 in %2 ms geladen (Engine %3 ms, Vorschaubilder %4 ms, Texturen %5 ms).</translation>
    </message>
    <message>
        <source>The file places %1 camera(s): View › glTF Cameras looks through them; the automatic view looks from the side of the first.</source>
        <translation>Die Datei platziert %1 Kamera(s): Ansicht › glTF-Kameras schaut durch sie; die automatische Ansicht blickt von der Seite der ersten.</translation>
    </message>
    <message>
        <source>Could not load %1; the current scene is kept.</source>
        <translation>%1 konnte nicht geladen werden; die aktuelle Szene bleibt.</translation>
    </message>
    <message>
        <source>Could not load %1; no scene is open.</source>
        <translation>%1 konnte nicht geladen werden; es ist keine Szene geöffnet.</translation>
    </message>
    <message>
        <source>Load failed</source>
        <translation>Laden fehlgeschlagen</translation>
    </message>
    <message>
        <source>Could not load %1:
%2

The current scene is kept.</source>
        <translation>%1 konnte nicht geladen werden:
%2

Die aktuelle Szene bleibt erhalten.</translation>
    </message>
    <message>
        <source>Could not load %1:
%2

No scene is open.</source>
        <translation>%1 konnte nicht geladen werden:
%2

Es ist keine Szene geöffnet.</translation>
    </message>
    <message>
        <source>(no recent files)</source>
        <translation>(keine zuletzt geöffneten Dateien)</translation>
    </message>
    <message>
        <source>Open glTF scene</source>
        <translation>glTF-Szene öffnen</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb);;All files (*)</source>
        <translation>glTF-Szenen (*.gltf *.glb);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Texture cache cleared: %1 files deleted from %2; the next load compresses again.</source>
        <translation>Texturcache geleert: %1 Dateien aus %2 gelöscht; das nächste Laden komprimiert erneut.</translation>
    </message>
    <message>
        <source>Texture %1: %2 cache files deleted; reloading to compress it again.</source>
        <translation>Textur %1: %2 Cache-Dateien gelöscht; die Szene wird neu geladen und die Textur neu komprimiert.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LogDock</name>
    <message>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <source>info</source>
        <translation>Info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MainWindow</name>
    <message>
        <source>No scene. Open a glTF file or a built-in scene from the File menu.</source>
        <translation>Keine Szene. Öffnen Sie eine glTF-Datei oder eine eingebaute Szene über das Menü „Datei“.</translation>
    </message>
    <message>
        <source>Sherpa</source>
        <translation>Sherpa</translation>
    </message>
    <message>
        <source>%1: %2 nodes, %3 primitives, %4 instances, %5 materials, %6 textures</source>
        <translation>%1: %2 Knoten, %3 Primitive, %4 Instanzen, %5 Materialien, %6 Texturen</translation>
    </message>
    <message>
        <source>%1 — Sherpa</source>
        <translation>%1 — Sherpa</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>Ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Built-in Scenes</source>
        <translation>&amp;Eingebaute Szenen</translation>
    </message>
    <message>
        <source>Default scene</source>
        <translation>Standardszene</translation>
    </message>
    <message>
        <source>Grid, 10 × 10</source>
        <translation>Raster, 10 × 10</translation>
    </message>
    <message>
        <source>Grid, 100 × 100</source>
        <translation>Raster, 100 × 100</translation>
    </message>
    <message>
        <source>Grid, 1000 × 1000</source>
        <translation>Raster, 1000 × 1000</translation>
    </message>
    <message>
        <source>Re&amp;load</source>
        <translation>&amp;Neu laden</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Schließen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Clear list</source>
        <translation>Liste leeren</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Debug View</source>
        <translation>&amp;Debug-Ansicht</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>Ü&amp;berlagerungen</translation>
    </message>
    <message>
        <source>Frame &amp;All (F)</source>
        <translation>&amp;Alles einpassen (F)</translation>
    </message>
    <message>
        <source>Frame &amp;Selection (Shift+F)</source>
        <translation>Au&amp;swahl einpassen (Umschalt+F)</translation>
    </message>
    <message>
        <source>&amp;Fly Mode (WASD, Q/E)</source>
        <translation>&amp;Flugmodus (WASD, Q/E)</translation>
    </message>
    <message>
        <source>glTF &amp;Cameras</source>
        <translation>glTF-&amp;Kameras</translation>
    </message>
    <message>
        <source>&amp;Docks</source>
        <translation>&amp;Docks</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;Culling</source>
        <translation>&amp;Culling</translation>
    </message>
    <message>
        <source>&amp;Freeze Culling Camera</source>
        <translation>Culling-Kamera &amp;einfrieren</translation>
    </message>
    <message>
        <source>&amp;Colour Boxes by Result</source>
        <translation>Quader nach Ergebnis &amp;färben</translation>
    </message>
    <message>
        <source>&amp;Method</source>
        <translation>&amp;Methode</translation>
    </message>
    <message>
        <source>Bounding sphere</source>
        <translation>Hüllkugel</translation>
    </message>
    <message>
        <source>P-vertex (AABB)</source>
        <translation>P-Vertex (AABB)</translation>
    </message>
    <message>
        <source>Exact (SAT)</source>
        <translation>Exakt (SAT)</translation>
    </message>
    <message>
        <source>&amp;Path</source>
        <translation>&amp;Pfad</translation>
    </message>
    <message>
        <source>CPU</source>
        <translation>CPU</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Einstellungen</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Texture Quality</source>
        <translation>&amp;Texturqualität</translation>
    </message>
    <message>
        <source>Fast</source>
        <translation>Schnell</translation>
    </message>
    <message>
        <source>Balanced</source>
        <translation>Ausgewogen</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>Beste</translation>
    </message>
    <message>
        <source>Texture Cache &amp;Directory…</source>
        <translation>&amp;Verzeichnis des Textur-Caches …</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Sherpa</source>
        <translation>&amp;Über Sherpa</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>none (Vulkan unavailable)</source>
        <translation>keines (Vulkan nicht verfügbar)</translation>
    </message>
    <message>
        <source>About Sherpa</source>
        <translation>Über Sherpa</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Sherpa %1&lt;/h3&gt;&lt;p&gt;A glTF 2.0 scene inspection editor.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;Vulkan devices: %4&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sherpa %1&lt;/h3&gt;&lt;p&gt;Ein Editor zur Untersuchung von glTF-2.0-Szenen.&lt;/p&gt;&lt;p&gt;Qt %2 (gebaut mit %3)&lt;br&gt;Vulkan-Geräte: %4&lt;/p&gt;</translation>
    </message>
    <message>
        <source>GPU (compute shader, indirect draws)</source>
        <translation>GPU (Compute-Shader, indirekte Draws)</translation>
    </message>
    <message>
        <source>&amp;Missing Textures as Checker</source>
        <translation>&amp;Fehlende Texturen als Schachbrett</translation>
    </message>
    <message>
        <source>Draw material slots whose image is missing or undecodable as a magenta/black checker (colour slots); off: the glTF defaults (white, flat normal)</source>
        <translation>Materialslots, deren Bild fehlt oder nicht dekodierbar ist, als Magenta/Schwarz-Schachbrett zeichnen (Farbslots); aus: die glTF-Standardwerte (weiß, flache Normale)</translation>
    </message>
    <message>
        <source>&amp;UV Checker Density (checks per UV unit)</source>
        <translation>&amp;UV-Schachbrettdichte (Felder pro UV-Einheit)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MaterialDock</name>
    <message>
        <source>Material SSBO</source>
        <translation>Material-SSBO</translation>
    </message>
    <message>
        <source>No material selected.</source>
        <translation>Kein Material ausgewählt.</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(unbenannt)</translation>
    </message>
    <message>
        <source>Material %1 %2: 80-byte std430 record read back from the GPU material buffer at offset %3.</source>
        <translation>Material %1 %2: 80-Byte-std430-Datensatz, aus dem GPU-Materialpuffer bei Offset %3 zurückgelesen.</translation>
    </message>
    <message>
        <source>Material %1 %2: the importer&apos;s CPU record (no renderer attached, so texture fields hold glTF texture indices, not bindless slots).</source>
        <translation>Material %1 %2: der CPU-Datensatz des Importers (kein Renderer angebunden, daher enthalten die Texturfelder glTF-Texturindizes, keine Bindless-Slots).</translation>
    </message>
    <message>
        <source>⚠ Not drawn: %1. Sherpa does not implement %2, so this material is shown without %2.</source>
        <translation>⚠ Nicht gezeichnet: %1. Sherpa implementiert %2 nicht; dieses Material wird ohne %2 angezeigt.</translation>
    </message>
    <message>
        <source>this extension</source>
        <translation>diese Erweiterung</translation>
    </message>
    <message>
        <source>these extensions</source>
        <translation>diese Erweiterungen</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MaterialFieldsModel</name>
    <message>
        <source>absent</source>
        <translation>fehlt</translation>
    </message>
    <message>
        <source>texture %1</source>
        <translation>Textur %1</translation>
    </message>
    <message>
        <source>bufferView %1</source>
        <translation>bufferView %1</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>erzeugt</translation>
    </message>
    <message>
        <source> → image %1 (%2)</source>
        <translation> → Bild %1 (%2)</translation>
    </message>
    <message>
        <source> → cache: %1</source>
        <translation> → Cache: %1</translation>
    </message>
    <message>
        <source>Double-click to show this texture in the texture dock</source>
        <translation>Doppelklick zeigt diese Textur im Textur-Dock</translation>
    </message>
    <message>
        <source>none (0x%1)</source>
        <translation>keine (0x%1)</translation>
    </message>
    <message>
        <source>default texture</source>
        <translation>Standardtextur</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>glTF property</source>
        <translation>glTF-Eigenschaft</translation>
    </message>
    <message>
        <source>Texture chain</source>
        <translation>Texturkette</translation>
    </message>
    <message>
        <source>Byte offset in the record</source>
        <translation>Byte-Versatz im Datensatz</translation>
    </message>
    <message>
        <source>transmission %1, volume %2, diffuse transmission %3, dispersion %4</source>
        <translation>Transmission %1, Volumen %2, diffuse Transmission %3, Dispersion %4</translation>
    </message>
    <message>
        <source> (distance infinite: none)</source>
        <translation> (Distanz unendlich: keine)</translation>
    </message>
    <message>
        <source>ior %1, specular %2, clearcoat %3, sheen %4</source>
        <translation>ior %1, specular %2, clearcoat %3, sheen %4</translation>
    </message>
    <message>
        <source>anisotropy %1, iridescence %2</source>
        <translation>Anisotropie %1, Irisieren %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MeshDock</name>
    <message>
        <source>max %1°, mean %2°, %3 handedness flips</source>
        <translation>max. %1°, Mittel %2°, %3 Händigkeitswechsel</translation>
    </message>
    <message>
        <source>Mesh Attributes</source>
        <translation>Mesh-Attribute</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vertices</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>Jump to vertex</source>
        <translation>Zu Vertex springen</translation>
    </message>
    <message>
        <source>Compare tangents</source>
        <translation>Tangenten vergleichen</translation>
    </message>
    <message>
        <source>Regenerate MikkTSpace tangents and show the angle to the mesh&apos;s tangents per vertex (sortable column)</source>
        <translation>MikkTSpace-Tangenten neu erzeugen und je Vertex den Winkel zu den Tangenten des Meshes zeigen (sortierbare Spalte)</translation>
    </message>
    <message>
        <source>No primitive selected. Select a node or primitive in the scene tree or click an object in the viewport.</source>
        <translation>Kein Primitiv ausgewählt. Wählen Sie einen Knoten oder ein Primitiv im Szenenbaum oder klicken Sie ein Objekt im Viewport an.</translation>
    </message>
    <message>
        <source> (unwelded for flat normals)</source>
        <translation> (für flache Normalen aufgetrennt)</translation>
    </message>
    <message>
        <source>Comparing…</source>
        <translation>Vergleiche …</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>Segmente</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>%1 line segments</source>
        <translation>%1 Liniensegmente</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 Punkte</translation>
    </message>
    <message>
        <source>%1 triangles</source>
        <translation>%1 Dreiecke</translation>
    </message>
    <message>
        <source>Mesh %1 primitive %2 &quot;%3&quot;: %4 vertices (file: %5), %6, material %7, %8 on the GPU%9</source>
        <translation>Mesh %1 Primitiv %2 „%3“: %4 Vertices (Datei: %5), %6, Material %7, %8 auf der GPU%9</translation>
    </message>
    <message>
        <source>; %1 %2: %3 → %4 decoded in %5 ms</source>
        <translation>; %1 %2: %3 → %4 dekodiert in %5 ms</translation>
    </message>
    <message>
        <source>Instances (%1)</source>
        <translation>Instanzen (%1)</translation>
    </message>
    <message>
        <source>Instances</source>
        <translation>Instanzen</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MorphWeightsPanel</name>
    <message>
        <source>No morph targets in this scene.</source>
        <translation>Keine Morph-Ziele in dieser Szene.</translation>
    </message>
    <message>
        <source>Override mesh %1</source>
        <translation>Mesh %1 überschreiben</translation>
    </message>
    <message>
        <source>Override %1</source>
        <translation>%1 überschreiben</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>Ziel %1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MotionController</name>
    <message>
        <source>At %1 s: %2</source>
        <translation>Bei %1 s: %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ReloadController</name>
    <message>
        <source>When the File &amp;Changes</source>
        <translation>Wenn sich die Datei &amp;ändert</translation>
    </message>
    <message>
        <source>&amp;Offer to Reload</source>
        <translation>Neu laden &amp;anbieten</translation>
    </message>
    <message>
        <source>&amp;Reload Automatically</source>
        <translation>Automatisch &amp;neu laden</translation>
    </message>
    <message>
        <source>The open file, its buffers and its images are watched on disk</source>
        <translation>Die geöffnete Datei, ihre Puffer und Bilder werden auf dem Datenträger überwacht</translation>
    </message>
    <message>
        <source>%1 changed on disk: reloading.</source>
        <translation>%1 wurde auf dem Datenträger geändert: wird neu geladen.</translation>
    </message>
    <message>
        <source>%1 changed on disk.</source>
        <translation>%1 wurde auf dem Datenträger geändert.</translation>
    </message>
    <message>
        <source>%1 changed on disk. Reload the scene?</source>
        <translation>%1 wurde auf dem Datenträger geändert. Szene neu laden?</translation>
    </message>
    <message>
        <source>File changed</source>
        <translation>Datei geändert</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Neu laden</translation>
    </message>
    <message>
        <source>&amp;Keep the Loaded Scene</source>
        <translation>Geladene Szene &amp;behalten</translation>
    </message>
    <message>
        <source>Settings › When the File Changes › Reload Automatically reloads without asking.</source>
        <translation>Einstellungen › Wenn sich die Datei ändert › Automatisch neu laden lädt ohne Nachfrage neu.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::RenderController</name>
    <message>
        <source>No Vulkan instance: the viewport cannot render.</source>
        <translation>Keine Vulkan-Instanz: der Viewport kann nicht rendern.</translation>
    </message>
    <message>
        <source>Rendering on %1 (renderer ready in %2 ms).</source>
        <translation>Rendern auf %1 (Renderer nach %2 ms bereit).</translation>
    </message>
    <message>
        <source>The renderer could not start: %1</source>
        <translation>Der Renderer konnte nicht starten: %1</translation>
    </message>
    <message>
        <source>Rendering stopped: %1</source>
        <translation>Rendern angehalten: %1</translation>
    </message>
    <message>
        <source>GPU culling failed: %1</source>
        <translation>GPU-Culling fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Ray tracing is off (--rt off): no acceleration structures.</source>
        <translation>Raytracing ist aus (--rt off): keine Beschleunigungsstrukturen.</translation>
    </message>
    <message>
        <source>The device does not ray trace: no acceleration structures.</source>
        <translation>Das Gerät beherrscht kein Raytracing: keine Beschleunigungsstrukturen.</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>Keine Szene.</translation>
    </message>
    <message>
        <source>The scene has no triangles: no acceleration structures.</source>
        <translation>Die Szene hat keine Dreiecke: keine Beschleunigungsstrukturen.</translation>
    </message>
    <message>
        <source>first frame %1 ms (makes the pipelines)</source>
        <translation>erstes Bild %1 ms (erstellt die Pipelines)</translation>
    </message>
    <message>
        <source>%1 fps, %2 ms per frame</source>
        <translation>%1 fps, %2 ms pro Bild</translation>
    </message>
    <message>
        <source> (GPU %1 ms)</source>
        <translation> (GPU %1 ms)</translation>
    </message>
    <message>
        <source>, resolution %1%</source>
        <translation>, Auflösung %1 %</translation>
    </message>
    <message>
        <source>, path traced %1 spp</source>
        <translation>, %1 spp pfadverfolgt</translation>
    </message>
    <message>
        <source>, estimated error %1%</source>
        <translation>, geschätzter Fehler %1 %</translation>
    </message>
    <message>
        <source>Mean of the last %1 frames, not counting the renderer&apos;s first (pipeline creation). While the camera moves or an animation plays on a slow device, frames are drawn at a lower resolution and without shadows to keep %2 fps; at rest or paused the full frame follows.</source>
        <translation>Mittel der letzten %1 Bilder ohne das erste des Renderers (Pipeline-Erstellung). Während sich die Kamera bewegt oder eine Animation läuft, werden Bilder auf einem langsamen Gerät mit geringerer Auflösung und ohne Schatten gezeichnet, um %2 fps zu halten; in Ruhe oder angehalten folgt das volle Bild.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SceneTreeDock</name>
    <message>
        <source>Scene Tree</source>
        <translation>Szenenbaum</translation>
    </message>
    <message>
        <source>Filter by name…</source>
        <translation>Nach Namen filtern …</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SceneTreeModel</name>
    <message>
        <source>Scene %1</source>
        <translation>Szene %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>Primitive %1</source>
        <translation>Primitiv %1</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Kamera %1</translation>
    </message>
    <message>
        <source>displayed</source>
        <translation>angezeigt</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>Matrix</translation>
    </message>
    <message>
        <source>T %1  R %2  S %3</source>
        <translation>T %1  R %2  S %3</translation>
    </message>
    <message>
        <source>skipped: %1</source>
        <translation>übersprungen: %1</translation>
    </message>
    <message>
        <source>%1, %2 vertices, %3 triangles</source>
        <translation>%1, %2 Vertices, %3 Dreiecke</translation>
    </message>
    <message>
        <source>directional</source>
        <translation>gerichtet</translation>
    </message>
    <message>
        <source>point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <source>spot</source>
        <translation>Spot</translation>
    </message>
    <message>
        <source>perspective</source>
        <translation>perspektivisch</translation>
    </message>
    <message>
        <source>orthographic</source>
        <translation>orthografisch</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>primitive</source>
        <translation>Primitiv</translation>
    </message>
    <message>
        <source>material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>light</source>
        <translation>Licht</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <source>Scene %1: %2</source>
        <translation>Szene %1: %2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>T %1</translation>
    </message>
    <message>
        <source>rotated</source>
        <translation>gedreht</translation>
    </message>
    <message>
        <source>S %1</source>
        <translation>S %1</translation>
    </message>
    <message>
        <source>identity</source>
        <translation>Identität</translation>
    </message>
    <message>
        <source>%1 vertices, %2 triangles</source>
        <translation>%1 Vertices, %2 Dreiecke</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Skin %1</source>
        <translation>Skin %1</translation>
    </message>
    <message>
        <source>Skin %1: %2</source>
        <translation>Skin %1: %2</translation>
    </message>
    <message>
        <source>Animation %1</source>
        <translation>Animation %1</translation>
    </message>
    <message>
        <source>Animation %1: %2</source>
        <translation>Animation %1: %2</translation>
    </message>
    <message>
        <source>Channel %1</source>
        <translation>Kanal %1</translation>
    </message>
    <message>
        <source>Sampler %1</source>
        <translation>Sampler %1</translation>
    </message>
    <message>
        <source>skin</source>
        <translation>Skin</translation>
    </message>
    <message>
        <source>animation</source>
        <translation>Animation</translation>
    </message>
    <message>
        <source>channel</source>
        <translation>Kanal</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>Sampler</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 Gelenke</translation>
    </message>
    <message>
        <source>%1, skeleton %2</source>
        <translation>%1, Skelett %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>%1 s, %2 channels</source>
        <translation>%1 s, %2 Kanäle</translation>
    </message>
    <message>
        <source>%1, %2 samplers, %3 keys, %4 to %5 s</source>
        <translation>%1, %2 Sampler, %3 Keyframes, %4 bis %5 s</translation>
    </message>
    <message>
        <source>%1 %2, sampler %3</source>
        <translation>%1 %2, Sampler %3</translation>
    </message>
    <message>
        <source>%1, %2 keys</source>
        <translation>%1, %2 Keyframes</translation>
    </message>
    <message>
        <source>%1, %2 to %3 s</source>
        <translation>%1, %2 bis %3 s</translation>
    </message>
    <message>
        <source>×%1 GPU instances</source>
        <translation>×%1 GPU-Instanzen</translation>
    </message>
    <message>
        <source>×%1 GPU instances (of %2 rows)</source>
        <translation>×%1 GPU-Instanzen (von %2 Zeilen)</translation>
    </message>
    <message>
        <source>Validation messages name this (see the Validation dock).</source>
        <translation>Validierungsmeldungen nennen dieses Objekt (siehe Validierungs-Dock).</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SelectionController</name>
    <message>
        <source>node %1</source>
        <translation>Knoten %1</translation>
    </message>
    <message>
        <source>primitive %1</source>
        <translation>Primitiv %1</translation>
    </message>
    <message>
        <source>accessor %1: %2 of primitive %3</source>
        <translation>Accessor %1: %2 von Primitiv %3</translation>
    </message>
    <message>
        <source>triangle %1</source>
        <translation>Dreieck %1</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>Vertex %1</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>texture %1</source>
        <translation>Textur %1</translation>
    </message>
    <message>
        <source>→ nothing the editor can select (%1).</source>
        <translation>→ nichts, was der Editor auswählen kann (%1).</translation>
    </message>
    <message>
        <source>→ %1</source>
        <translation>→ %1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TextureDock</name>
    <message>
        <source>Texture Cache</source>
        <translation>Textur-Cache</translation>
    </message>
    <message>
        <source>Recompress selected</source>
        <translation>Auswahl neu komprimieren</translation>
    </message>
    <message>
        <source>Clear cache</source>
        <translation>Cache leeren</translation>
    </message>
    <message>
        <source>Open cache folder</source>
        <translation>Cache-Ordner öffnen</translation>
    </message>
    <message>
        <source>no renderer</source>
        <translation>kein Renderer</translation>
    </message>
    <message>
        <source>%1 textures, %2 encoded on disk, %3 on the GPU, thumbnails decoded in %4 ms</source>
        <translation>%1 Texturen, %2 kodiert auf der Festplatte, %3 auf der GPU, Vorschaubilder in %4 ms dekodiert</translation>
    </message>
    <message>
        <source>Delete the selected texture&apos;s cache files and load the scene again, which compresses it anew with the current quality</source>
        <translation>Die Cache-Dateien der ausgewählten Textur löschen und die Szene neu laden, wodurch sie mit der aktuellen Qualität neu komprimiert wird</translation>
    </message>
    <message>
        <source>Delete every KTX2 file in the texture cache directory</source>
        <translation>Alle KTX2-Dateien im Texturcache-Verzeichnis löschen</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TextureTableModel</name>
    <message>
        <source>Texture %1</source>
        <translation>Textur %1</translation>
    </message>
    <message>
        <source>no image</source>
        <translation>kein Bild</translation>
    </message>
    <message>
        <source>bufferView %1</source>
        <translation>bufferView %1</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>erzeugt</translation>
    </message>
    <message>
        <source>undecodable</source>
        <translation>nicht dekodierbar</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Textur</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>Content hash</source>
        <translation>Inhalts-Hash</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Größe</translation>
    </message>
    <message>
        <source>Mips</source>
        <translation>Mips</translation>
    </message>
    <message>
        <source>Disk bytes</source>
        <translation>Bytes auf Festplatte</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU-Bytes</translation>
    </message>
    <message>
        <source>Decode ms</source>
        <translation>Dekodieren ms</translation>
    </message>
    <message>
        <source>Encode ms</source>
        <translation>Kodieren ms</translation>
    </message>
    <message>
        <source>PSNR</source>
        <translation>PSNR</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>hit</source>
        <translation>Treffer</translation>
    </message>
    <message>
        <source>miss</source>
        <translation>Fehltreffer</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>veraltet</translation>
    </message>
    <message>
        <source>recompressed</source>
        <translation>neu komprimiert</translation>
    </message>
    <message>
        <source>fallback</source>
        <translation>Ersatz (RGBA8)</translation>
    </message>
    <message>
        <source>missing: %1</source>
        <translation>fehlt: %1</translation>
    </message>
    <message>
        <source>Container</source>
        <translation>Container</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <source>Scrub; the ticks are the animation&apos;s key times</source>
        <translation>Zeit wählen; die Striche sind die Keyframe-Zeiten der Animation</translation>
    </message>
    <message>
        <source>No animation</source>
        <translation>Keine Animation</translation>
    </message>
    <message>
        <source>Animation %1</source>
        <translation>Animation %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>no animation</source>
        <translation>keine Animation</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TriangleTableModel</name>
    <message>
        <source>vertex 0</source>
        <translation>Vertex 0</translation>
    </message>
    <message>
        <source>vertex 1</source>
        <translation>Vertex 1</translation>
    </message>
    <message>
        <source>vertex 2</source>
        <translation>Vertex 2</translation>
    </message>
    <message>
        <source>area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>length</source>
        <translation>Länge</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ValidationDock</name>
    <message>
        <source>Validation</source>
        <translation>Validierung</translation>
    </message>
    <message>
        <source>Filter by code, pointer or text…</source>
        <translation>Nach Code, Zeiger oder Text filtern…</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>Keine Szene.</translation>
    </message>
    <message>
        <source>No messages: nothing to report about this file.</source>
        <translation>Keine Meldungen: zu dieser Datei gibt es nichts zu berichten.</translation>
    </message>
    <message>
        <source>%1 errors, %2 warnings, %3 information, %4 hints. Click a message to select what it names.</source>
        <translation>%1 Fehler, %2 Warnungen, %3 Informationen, %4 Hinweise. Eine Meldung anklicken wählt aus, was sie nennt.</translation>
    </message>
    <message>
        <source>The list is truncated.</source>
        <translation>Die Liste ist gekürzt.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ValidationModel</name>
    <message>
        <source>Errors (%1)</source>
        <translation>Fehler (%1)</translation>
    </message>
    <message>
        <source>Warnings (%1)</source>
        <translation>Warnungen (%1)</translation>
    </message>
    <message>
        <source>Information (%1)</source>
        <translation>Informationen (%1)</translation>
    </message>
    <message>
        <source>Hints (%1)</source>
        <translation>Hinweise (%1)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>(the whole file)</source>
        <translation>(die ganze Datei)</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::VariantMenu</name>
    <message>
        <source>default materials</source>
        <translation>Standardmaterialien</translation>
    </message>
    <message>
        <source>Material variant: %1 (%2 primitive(s), %3 draw(s) changed material; %4 GPU bytes uploaded%5; nothing reloaded).</source>
        <translation>Materialvariante: %1 (%2 Primitive, %3 Draws mit anderem Material; %4 GPU-Bytes hochgeladen%5; nichts neu geladen).</translation>
    </message>
    <message>
        <source>, culling lists rebuilt for a changed alpha mode</source>
        <translation>, Culling-Listen wegen geänderten Alpha-Modus neu aufgebaut</translation>
    </message>
    <message>
        <source>Va&amp;riants</source>
        <translation>Va&amp;rianten</translation>
    </message>
    <message>
        <source>&amp;Default Materials</source>
        <translation>&amp;Standardmaterialien</translation>
    </message>
    <message>
        <source>The file has no material variants</source>
        <translation>Die Datei hat keine Materialvarianten</translation>
    </message>
    <message>
        <source>; ray tracer: %1 geometry record(s), %2 bytes</source>
        <translation>; Raytracer: %1 Geometrie-Einträge, %2 Bytes</translation>
    </message>
    <message>
        <source>, TLAS rebuilt: any-hit forced on %1 BLAS built opaque, back-face culling off on %2</source>
        <translation>, TLAS neu aufgebaut: Any-Hit erzwungen für %1 opak gebaute BLAS, Rückseiten-Culling aus für %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::VertexTableModel</name>
    <message>
        <source>tangent error (deg)</source>
        <translation>Tangentenfehler (Grad)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ViewController</name>
    <message>
        <source>View: %1</source>
        <translation>Ansicht: %1</translation>
    </message>
    <message>
        <source>Overlays</source>
        <translation>Überlagerungen</translation>
    </message>
    <message>
        <source>Overlays (%1)</source>
        <translation>Überlagerungen (%1)</translation>
    </message>
    <message>
        <source>Overlays: none shown</source>
        <translation>Überlagerungen: keine angezeigt</translation>
    </message>
    <message>
        <source>Overlays: %1</source>
        <translation>Überlagerungen: %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>the room</source>
        <translation>den Raum</translation>
    </message>
    <message>
        <source>Environment: %1.</source>
        <translation>Umgebung: %1.</translation>
    </message>
    <message>
        <source>Shadows: %1 cascades, %2 PCF taps; the viewport&apos;s maps stay %3x%3 texels (fixed when its renderer is made), not %4</source>
        <translation>Schatten: %1 Kaskaden, %2 PCF-Abtastungen; die Maps des Viewports bleiben %3x%3 Texel (beim Erzeugen seines Renderers festgelegt), nicht %4</translation>
    </message>
    <message>
        <source>(the scene has no cameras)</source>
        <translation>(die Szene hat keine Kameras)</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Kamera %1</translation>
    </message>
</context>
</TS>
