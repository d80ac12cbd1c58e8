<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
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
        <translation>unknown (%1)</translation>
    </message>
    <message>
        <source>authored</source>
        <translation>authored</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>generated</translation>
    </message>
    <message>
        <source>defaulted</source>
        <translation>defaulted</translation>
    </message>
    <message>
        <source>colour (sRGB)</source>
        <translation>colour (sRGB)</translation>
    </message>
    <message>
        <source>linear data</source>
        <translation>linear data</translation>
    </message>
    <message>
        <source>normal map</source>
        <translation>normal map</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>unused</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>yes</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
</context>
<context>
    <name>LabChart</name>
    <message>
        <source>time (%1)</source>
        <translation>time (%1)</translation>
    </message>
    <message>
        <source>Pareto front</source>
        <translation>Pareto front</translation>
    </message>
    <message>
        <source>%1 (in use)</source>
        <translation>%1 (in use)</translation>
    </message>
</context>
<context>
    <name>ViewCatalog</name>
    <message>
        <source>Lit</source>
        <translation>Lit</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normals</translation>
    </message>
    <message>
        <source>Tangents</source>
        <translation>Tangents</translation>
    </message>
    <message>
        <source>Bitangents</source>
        <translation>Bitangents</translation>
    </message>
    <message>
        <source>Handedness (tangent w)</source>
        <translation>Handedness (tangent w)</translation>
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
        <translation>UV 0 checker</translation>
    </message>
    <message>
        <source>UV 1 checker</source>
        <translation>UV 1 checker</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>Base colour</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>Metallic</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>Roughness</translation>
    </message>
    <message>
        <source>Occlusion</source>
        <translation>Occlusion</translation>
    </message>
    <message>
        <source>Emissive</source>
        <translation>Emissive</translation>
    </message>
    <message>
        <source>Geometric vs shading normal</source>
        <translation>Geometric vs shading normal</translation>
    </message>
    <message>
        <source>Tangent provenance</source>
        <translation>Tangent provenance</translation>
    </message>
    <message>
        <source>Shading normal</source>
        <translation>Shading normal</translation>
    </message>
    <message>
        <source>Specular (F0)</source>
        <translation>Specular (F0)</translation>
    </message>
    <message>
        <source>Joint influence</source>
        <translation>Joint influence</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>Wireframe</translation>
    </message>
    <message>
        <source>Normal glyphs</source>
        <translation>Normal glyphs</translation>
    </message>
    <message>
        <source>Tangent glyphs</source>
        <translation>Tangent glyphs</translation>
    </message>
    <message>
        <source>Bitangent glyphs</source>
        <translation>Bitangent glyphs</translation>
    </message>
    <message>
        <source>Bounding boxes</source>
        <translation>Bounding boxes</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>Skeleton</translation>
    </message>
    <message>
        <source>Sun shadow</source>
        <translation>Sun shadow</translation>
    </message>
    <message>
        <source>Ambient occlusion (rays)</source>
        <translation>Ambient occlusion (rays)</translation>
    </message>
    <message>
        <source>Shadow error (maps vs rays)</source>
        <translation>Shadow error (maps vs rays)</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>Index of refraction</translation>
    </message>
    <message>
        <source>Specular weight</source>
        <translation>Specular weight</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>Specular colour</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>Transmission</translation>
    </message>
    <message>
        <source>Volume thickness</source>
        <translation>Volume thickness</translation>
    </message>
    <message>
        <source>Volume attenuation</source>
        <translation>Volume attenuation</translation>
    </message>
    <message>
        <source>Diffuse transmission</source>
        <translation>Diffuse transmission</translation>
    </message>
    <message>
        <source>Clearcoat</source>
        <translation>Clearcoat</translation>
    </message>
    <message>
        <source>Clearcoat roughness</source>
        <translation>Clearcoat roughness</translation>
    </message>
    <message>
        <source>Clearcoat normal</source>
        <translation>Clearcoat normal</translation>
    </message>
    <message>
        <source>Sheen colour</source>
        <translation>Sheen colour</translation>
    </message>
    <message>
        <source>Sheen roughness</source>
        <translation>Sheen roughness</translation>
    </message>
    <message>
        <source>Anisotropy strength</source>
        <translation>Anisotropy strength</translation>
    </message>
    <message>
        <source>Anisotropy direction</source>
        <translation>Anisotropy direction</translation>
    </message>
    <message>
        <source>Iridescence</source>
        <translation>Iridescence</translation>
    </message>
    <message>
        <source>Iridescence thickness</source>
        <translation>Iridescence thickness</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AccelerationDock</name>
    <message>
        <source>Acceleration Structures</source>
        <translation>Acceleration Structures</translation>
    </message>
    <message>
        <source>%1 BLAS, %2 triangles, %3 built, %4 compacted (%5%), %6 batches, built in %7 ms</source>
        <translation>%1 BLAS, %2 triangles, %3 built, %4 compacted (%5%), %6 batches, built in %7 ms</translation>
    </message>
    <message>
        <source>TLAS: %1 instances of %2 node/mesh pairs, %3 deduplicated, %4 mirrored, %5 hidden, %6 non-finite; %7</source>
        <translation>TLAS: %1 instances of %2 node/mesh pairs, %3 deduplicated, %4 mirrored, %5 hidden, %6 non-finite; %7</translation>
    </message>
    <message>
        <source>Total on the GPU: %1 (scratch buffer %2)</source>
        <translation>Total on the GPU: %1 (scratch buffer %2)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AccelerationModel</name>
    <message>
        <source>%1 geometries (one per triangle primitive), %2 of them opaque (no any-hit)</source>
        <translation>%1 geometries (one per triangle primitive), %2 of them opaque (no any-hit)</translation>
    </message>
    <message>
        <source>mesh %1</source>
        <translation>mesh %1</translation>
    </message>
    <message>
        <source>Geometries (opaque)</source>
        <translation>Geometries (opaque)</translation>
    </message>
    <message>
        <source>Mesh</source>
        <translation>Mesh</translation>
    </message>
    <message>
        <source>Geometries</source>
        <translation>Geometries</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>Build ms</source>
        <translation>Build ms</translation>
    </message>
    <message>
        <source>Built</source>
        <translation>Built</translation>
    </message>
    <message>
        <source>Compacted</source>
        <translation>Compacted</translation>
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
        <translation>indices</translation>
    </message>
    <message>
        <source>authored</source>
        <translation>authored</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>generated</translation>
    </message>
    <message>
        <source>not uploaded</source>
        <translation>not uploaded</translation>
    </message>
    <message>
        <source>yes (%1 values)</source>
        <translation>yes (%1 values)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>%1 (stride %2)</source>
        <translation>%1 (stride %2)</translation>
    </message>
    <message>
        <source>Attribute</source>
        <translation>Attribute</translation>
    </message>
    <message>
        <source>Provenance</source>
        <translation>Provenance</translation>
    </message>
    <message>
        <source>Accessor</source>
        <translation>Accessor</translation>
    </message>
    <message>
        <source>Normalized</source>
        <translation>Normalized</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Count</translation>
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
        <translation>Buffer view</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU bytes</translation>
    </message>
    <message>
        <source>, normalized</source>
        <translation>, normalized</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>Component</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CommandLine</name>
    <message>
        <source>First frame of the scene %1 ms after launch.</source>
        <translation>First frame of the scene %1 ms after launch.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CompareController</name>
    <message>
        <source>Compare with glTF scene</source>
        <translation>Compare with glTF scene</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb);;All files (*)</source>
        <translation>glTF scenes (*.gltf *.glb);;All files (*)</translation>
    </message>
    <message>
        <source>Side B: %1 could not be loaded: %2</source>
        <translation>Side B: %1 could not be loaded: %2</translation>
    </message>
    <message>
        <source>Side B: %1 loaded.</source>
        <translation>Side B: %1 loaded.</translation>
    </message>
    <message>
        <source>Side B: loading %1…</source>
        <translation>Side B: loading %1…</translation>
    </message>
    <message>
        <source>%1, source textures</source>
        <translation>%1, source textures</translation>
    </message>
    <message>
        <source>Side B: loading %1 with tangents by %2…</source>
        <translation>Side B: loading %1 with tangents by %2…</translation>
    </message>
    <message>
        <source>%1, tangents: %2</source>
        <translation>%1, tangents: %2</translation>
    </message>
    <message>
        <source>Side A&apos;s tangents: %1 primitive(s) authored, %2 exact MikkTSpace, %3 none (no TANGENT, no normal texture: there B differs from no tangents).</source>
        <translation>Side A&apos;s tangents: %1 primitive(s) authored, %2 exact MikkTSpace, %3 none (no TANGENT, no normal texture: there B differs from no tangents).</translation>
    </message>
    <message>
        <source>Overlays and the selection highlight are drawn in the Raster mode only.</source>
        <translation>Overlays and the selection highlight are drawn in the Raster mode only.</translation>
    </message>
    <message>
        <source>The ray tracer cannot draw this frame: %1. Back to Raster.</source>
        <translation>The ray tracer cannot draw this frame: %1. Back to Raster.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CompareControls</name>
    <message>
        <source>Raster</source>
        <translation>Raster</translation>
    </message>
    <message>
        <source>Ray traced</source>
        <translation>Ray traced</translation>
    </message>
    <message>
        <source>Split (A | B)</source>
        <translation>Split (A | B)</translation>
    </message>
    <message>
        <source>Difference (heat map)</source>
        <translation>Difference (heat map)</translation>
    </message>
    <message>
        <source>Viewport &amp;Mode</source>
        <translation>Viewport &amp;Mode</translation>
    </message>
    <message>
        <source>Compare &amp;With (side B)</source>
        <translation>Compare &amp;With (side B)</translation>
    </message>
    <message>
        <source>Another Debug View</source>
        <translation>Another Debug View</translation>
    </message>
    <message>
        <source>The Ray Tracer</source>
        <translation>The Ray Tracer</translation>
    </message>
    <message>
        <source>Another File…</source>
        <translation>Another File…</translation>
    </message>
    <message>
        <source>Another File… (%1)</source>
        <translation>Another File… (%1)</translation>
    </message>
    <message>
        <source>Viewport: %1</source>
        <translation>Viewport: %1</translation>
    </message>
    <message>
        <source>Raster or ray traced frame, or side A (this view, rasterized) against side B with one camera. Split: drag the divider line (or Ctrl+drag anywhere) to move it.</source>
        <translation>Raster or ray traced frame, or side A (this view, rasterized) against side B with one camera. Split: drag the divider line (or Ctrl+drag anywhere) to move it.</translation>
    </message>
    <message>
        <source>ray tracer</source>
        <translation>ray tracer</translation>
    </message>
    <message>
        <source>no file</source>
        <translation>no file</translation>
    </message>
    <message>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <source>This File, Source Textures (no BC7/BC5)</source>
        <translation>This File, Source Textures (no BC7/BC5)</translation>
    </message>
    <message>
        <source>The rasterizer: every view, overlays and the selection</source>
        <translation>The rasterizer: every view, overlays and the selection</translation>
    </message>
    <message>
        <source>Primary rays through the acceleration structures: the surface-data views</source>
        <translation>Primary rays through the acceleration structures: the surface-data views</translation>
    </message>
    <message>
        <source>Side A left, side B right, one camera: drag the divider line (or Ctrl+drag anywhere) to move it</source>
        <translation>Side A left, side B right, one camera: drag the divider line (or Ctrl+drag anywhere) to move it</translation>
    </message>
    <message>
        <source>Heat map of |A − B| with its legend: mean, max, PSNR, % of pixels over the threshold</source>
        <translation>Heat map of |A − B| with its legend: mean, max, PSNR, % of pixels over the threshold</translation>
    </message>
    <message>
        <source>Difference &amp;Heat Scale</source>
        <translation>Difference &amp;Heat Scale</translation>
    </message>
    <message>
        <source>Difference &amp;Threshold</source>
        <translation>Difference &amp;Threshold</translation>
    </message>
    <message>
        <source>%1/255 and above at full heat</source>
        <translation>%1/255 and above at full heat</translation>
    </message>
    <message>
        <source>Automatic (99.9th percentile of the differences)</source>
        <translation>Automatic (99.9th percentile of the differences)</translation>
    </message>
    <message>
        <source>Over %1/255</source>
        <translation>Over %1/255</translation>
    </message>
    <message>
        <source>MikkTSpace, exact (vertices split per corner)</source>
        <translation>MikkTSpace, exact (vertices split per corner)</translation>
    </message>
    <message>
        <source>MikkTSpace, welded (last corner per vertex)</source>
        <translation>MikkTSpace, welded (last corner per vertex)</translation>
    </message>
    <message>
        <source>Lengyel (summed per vertex)</source>
        <translation>Lengyel (summed per vertex)</translation>
    </message>
    <message>
        <source>This File, Tangents Regenerated By</source>
        <translation>This File, Tangents Regenerated By</translation>
    </message>
    <message>
        <source>What side B of the comparison draws: %1</source>
        <translation>What side B of the comparison draws: %1</translation>
    </message>
    <message>
        <source>Side B is shown in the Split and Difference modes (Viewport button); choosing it here switches to Split. Now: %1</source>
        <translation>Side B is shown in the Split and Difference modes (Viewport button); choosing it here switches to Split. Now: %1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CullingDock</name>
    <message>
        <source>Culling Statistics</source>
        <translation>Culling Statistics</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>Total</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Visible</translation>
    </message>
    <message>
        <source>Culled</source>
        <translation>Culled</translation>
    </message>
    <message>
        <source>False positives</source>
        <translation>False positives</translation>
    </message>
    <message>
        <source>Draw calls</source>
        <translation>Draw calls</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>CPU cull ms</source>
        <translation>CPU cull ms</translation>
    </message>
    <message>
        <source>GPU cull ms</source>
        <translation>GPU cull ms</translation>
    </message>
    <message>
        <source>Hidden</source>
        <translation>Hidden</translation>
    </message>
    <message>
        <source>visible</source>
        <translation>visible</translation>
    </message>
    <message>
        <source>culled</source>
        <translation>culled</translation>
    </message>
    <message>
        <source>update</source>
        <translation>update</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>No scene.</translation>
    </message>
    <message>
        <source>Pass &quot;%1&quot;: method %2, %3%4</source>
        <translation>Pass &quot;%1&quot;: method %2, %3%4</translation>
    </message>
    <message>
        <source>, culling camera frozen</source>
        <translation>, culling camera frozen</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: GPU path off (Culling › Path › GPU)</source>
        <translation>CPU/GPU agreement: GPU path off (Culling › Path › GPU)</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: ✔ both keep %1 of %2</source>
        <translation>CPU/GPU agreement: ✔ both keep %1 of %2</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: ✘ %1 objects differ (CPU keeps %2, GPU %3)</source>
        <translation>CPU/GPU agreement: ✘ %1 objects differ (CPU keeps %2, GPU %3)</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Pass</translation>
    </message>
    <message>
        <source>Renderer passes: none (culling off or no frame yet)</source>
        <translation>Renderer passes: none (culling off or no frame yet)</translation>
    </message>
    <message>
        <source>Renderer passes, last frame (cascades reused from the frame that drew them)</source>
        <translation>Renderer passes, last frame (cascades reused from the frame that drew them)</translation>
    </message>
    <message>
        <source>Renderer passes, last frame</source>
        <translation>Renderer passes, last frame</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::DifferenceLegend</name>
    <message>
        <source>|A − B|, largest of R, G, B (of 255)</source>
        <translation>|A − B|, largest of R, G, B (of 255)</translation>
    </message>
    <message>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <source>No frame compared yet.</source>
        <translation>No frame compared yet.</translation>
    </message>
    <message>
        <source>∞ (identical)</source>
        <translation>∞ (identical)</translation>
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
        <translation>mean %1
max %2
PSNR %3
%4% of %5 pixels over %6</translation>
    </message>
    <message>
        <source>≥ %1 (auto)</source>
        <translation>≥ %1 (auto)</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::EnvironmentMenu</name>
    <message>
        <source>&amp;Environment</source>
        <translation>&amp;Environment</translation>
    </message>
    <message>
        <source>&amp;None (Ambient Only)</source>
        <translation>&amp;None (Ambient Only)</translation>
    </message>
    <message>
        <source>&amp;Room (Built In)</source>
        <translation>&amp;Room (Built In)</translation>
    </message>
    <message>
        <source>&amp;Open HDR or EXR… (%1)</source>
        <translation>&amp;Open HDR or EXR… (%1)</translation>
    </message>
    <message>
        <source>&amp;Open HDR or EXR…</source>
        <translation>&amp;Open HDR or EXR…</translation>
    </message>
    <message>
        <source>&amp;Background</source>
        <translation>&amp;Background</translation>
    </message>
    <message>
        <source>&amp;Blurred</source>
        <translation>&amp;Blurred</translation>
    </message>
    <message>
        <source>&amp;Solid Colour</source>
        <translation>&amp;Solid Colour</translation>
    </message>
    <message>
        <source>Rotate −15° (now %1°)</source>
        <translation>Rotate −15° (now %1°)</translation>
    </message>
    <message>
        <source>Rotate +15° (now %1°)</source>
        <translation>Rotate +15° (now %1°)</translation>
    </message>
    <message>
        <source>Brighter (intensity %1)</source>
        <translation>Brighter (intensity %1)</translation>
    </message>
    <message>
        <source>Darker</source>
        <translation>Darker</translation>
    </message>
    <message>
        <source>Reset Rotation and Intensity</source>
        <translation>Reset Rotation and Intensity</translation>
    </message>
    <message>
        <source>Default &amp;Sun</source>
        <translation>Default &amp;Sun</translation>
    </message>
    <message>
        <source>Energy &amp;Compensation (Multiple Scattering)</source>
        <translation>Energy &amp;Compensation (Multiple Scattering)</translation>
    </message>
    <message>
        <source>&amp;Tone Mapping</source>
        <translation>&amp;Tone Mapping</translation>
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
        <translation>&amp;Linear (Clamp)</translation>
    </message>
    <message>
        <source>Exposure +½ Stop (now %1 EV)</source>
        <translation>Exposure +½ Stop (now %1 EV)</translation>
    </message>
    <message>
        <source>Exposure −½ Stop</source>
        <translation>Exposure −½ Stop</translation>
    </message>
    <message>
        <source>Exposure 0 EV</source>
        <translation>Exposure 0 EV</translation>
    </message>
    <message>
        <source>Open Environment</source>
        <translation>Open Environment</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>HDR images (*.hdr *.exr);;All files (*)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::InstanceTableModel</name>
    <message>
        <source>Row</source>
        <translation>Row</translation>
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
        <translation>Warning: %1</translation>
    </message>
    <message>
        <source>The Lab could not run: %1</source>
        <translation>The Lab could not run: %1</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Cancelled.</translation>
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
        <translation>Lab</translation>
    </message>
    <message>
        <source>Methods</source>
        <translation>Methods</translation>
    </message>
    <message>
        <source>Budget</source>
        <translation>Budget</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Run</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>Compute budget</source>
        <translation>Compute budget</translation>
    </message>
    <message>
        <source>Numbers</source>
        <translation>Numbers</translation>
    </message>
    <message>
        <source>Failures</source>
        <translation>Failures</translation>
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
        <translation>The family of methods to measure on the loaded scene</translation>
    </message>
    <message>
        <source>Measure every method of the family on this scene, off the UI thread</source>
        <translation>Measure every method of the family on this scene, off the UI thread</translation>
    </message>
    <message>
        <source>The numbers, as sherpa-cli lab --csv writes them</source>
        <translation>The numbers, as sherpa-cli lab --csv writes them</translation>
    </message>
    <message>
        <source>The chart, as sherpa-cli lab --chart writes it</source>
        <translation>The chart, as sherpa-cli lab --chart writes it</translation>
    </message>
    <message>
        <source>The chart as shown</source>
        <translation>The chart as shown</translation>
    </message>
    <message>
        <source>Pick a family and run it on %1.</source>
        <translation>Pick a family and run it on %1.</translation>
    </message>
    <message>
        <source>Open a scene to measure its methods.</source>
        <translation>Open a scene to measure its methods.</translation>
    </message>
    <message>
        <source>Compute the budget of %1.</source>
        <translation>Compute the budget of %1.</translation>
    </message>
    <message>
        <source>Open a scene to compute its budget.</source>
        <translation>Open a scene to compute its budget.</translation>
    </message>
    <message>
        <source>Running %1 on %2…</source>
        <translation>Running %1 on %2…</translation>
    </message>
    <message>
        <source>Computing the budget of %1…</source>
        <translation>Computing the budget of %1…</translation>
    </message>
    <message>
        <source>%1 against %2; time in %3</source>
        <translation>%1 against %2; time in %3</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>Could not write %1.</translation>
    </message>
    <message>
        <source>Export the Lab report</source>
        <translation>Export the Lab report</translation>
    </message>
    <message>
        <source>The line joins the Pareto front; the method in use is ringed.</source>
        <translation>The line joins the Pareto front; the method in use is ringed.</translation>
    </message>
    <message>
        <source>Click a point (or double-click a row) to use that method in the viewport: culling methods, and the cascade count and PCF taps of a shadow setting (the viewport&apos;s shadow maps keep their resolution, fixed when its renderer is made). Tangent and texture methods are measured here but the viewport has no switch for them, so clicking them changes nothing.</source>
        <translation>Click a point (or double-click a row) to use that method in the viewport: culling methods, and the cascade count and PCF taps of a shadow setting (the viewport&apos;s shadow maps keep their resolution, fixed when its renderer is made). Tangent and texture methods are measured here but the viewport has no switch for them, so clicking them changes nothing.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LabTableModel</name>
    <message>
        <source>Method</source>
        <translation>Method</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameters</translation>
    </message>
    <message>
        <source>Time (%1)</source>
        <translation>Time (%1)</translation>
    </message>
    <message>
        <source>Failures</source>
        <translation>Failures</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>not run</translation>
    </message>
    <message>
        <source>Cause</source>
        <translation>Cause</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Where</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Count</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU bytes</translation>
    </message>
    <message>
        <source>Unified</source>
        <translation>Unified</translation>
    </message>
    <message>
        <source>Stored</source>
        <translation>Stored</translation>
    </message>
    <message>
        <source>Needed</source>
        <translation>Needed</translation>
    </message>
    <message>
        <source>Oversized texture</source>
        <translation>Oversized texture</translation>
    </message>
    <message>
        <source>%1×%2: %3 texels per pixel at best, 1/%4 per side would look the same</source>
        <translation>%1×%2: %3 texels per pixel at best, 1/%4 per side would look the same</translation>
    </message>
    <message>
        <source>Unread attribute</source>
        <translation>Unread attribute</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>Finding</translation>
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
        <translation>Loading %1 cancelled; the result is discarded.</translation>
    </message>
    <message>
        <source>Texture cache directory</source>
        <translation>Texture cache directory</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>Loading %1…</translation>
    </message>
    <message>
        <source>1/4 parsing…</source>
        <translation>1/4 parsing…</translation>
    </message>
    <message>
        <source>2/4 geometry…</source>
        <translation>2/4 geometry…</translation>
    </message>
    <message>
        <source>3/4 tangents: mesh %1 of %2</source>
        <translation>3/4 tangents: mesh %1 of %2</translation>
    </message>
    <message>
        <source>4/4 textures: %1 of %2</source>
        <translation>4/4 textures: %1 of %2</translation>
    </message>
    <message>
        <source>Loaded %1 in %2 ms (engine %3 ms, thumbnails %4 ms, textures %5 ms).</source>
        <translation>Loaded %1 in %2 ms (engine %3 ms, thumbnails %4 ms, textures %5 ms).</translation>
    </message>
    <message>
        <source>The file places %1 camera(s): View › glTF Cameras looks through them; the automatic view looks from the side of the first.</source>
        <translation>The file places %1 camera(s): View › glTF Cameras looks through them; the automatic view looks from the side of the first.</translation>
    </message>
    <message>
        <source>Could not load %1; the current scene is kept.</source>
        <translation>Could not load %1; the current scene is kept.</translation>
    </message>
    <message>
        <source>Could not load %1; no scene is open.</source>
        <translation>Could not load %1; no scene is open.</translation>
    </message>
    <message>
        <source>Load failed</source>
        <translation>Load failed</translation>
    </message>
    <message>
        <source>Could not load %1:
%2

The current scene is kept.</source>
        <translation>Could not load %1:
%2

The current scene is kept.</translation>
    </message>
    <message>
        <source>Could not load %1:
%2

No scene is open.</source>
        <translation>Could not load %1:
%2

No scene is open.</translation>
    </message>
    <message>
        <source>(no recent files)</source>
        <translation>(no recent files)</translation>
    </message>
    <message>
        <source>Open glTF scene</source>
        <translation>Open glTF scene</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb);;All files (*)</source>
        <translation>glTF scenes (*.gltf *.glb);;All files (*)</translation>
    </message>
    <message>
        <source>Texture cache cleared: %1 files deleted from %2; the next load compresses again.</source>
        <translation>Texture cache cleared: %1 files deleted from %2; the next load compresses again.</translation>
    </message>
    <message>
        <source>Texture %1: %2 cache files deleted; reloading to compress it again.</source>
        <translation>Texture %1: %2 cache files deleted; reloading to compress it again.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LogDock</name>
    <message>
        <source>Log</source>
        <translation>Log</translation>
    </message>
    <message>
        <source>info</source>
        <translation>info</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>warning</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MainWindow</name>
    <message>
        <source>No scene. Open a glTF file or a built-in scene from the File menu.</source>
        <translation>No scene. Open a glTF file or a built-in scene from the File menu.</translation>
    </message>
    <message>
        <source>Sherpa</source>
        <translation>Sherpa</translation>
    </message>
    <message>
        <source>%1: %2 nodes, %3 primitives, %4 instances, %5 materials, %6 textures</source>
        <translation>%1: %2 nodes, %3 primitives, %4 instances, %5 materials, %6 textures</translation>
    </message>
    <message>
        <source>%1 — Sherpa</source>
        <translation>%1 — Sherpa</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Open…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Open &amp;Recent</translation>
    </message>
    <message>
        <source>&amp;Built-in Scenes</source>
        <translation>&amp;Built-in Scenes</translation>
    </message>
    <message>
        <source>Default scene</source>
        <translation>Default scene</translation>
    </message>
    <message>
        <source>Grid, 10 × 10</source>
        <translation>Grid, 10 × 10</translation>
    </message>
    <message>
        <source>Grid, 100 × 100</source>
        <translation>Grid, 100 × 100</translation>
    </message>
    <message>
        <source>Grid, 1000 × 1000</source>
        <translation>Grid, 1000 × 1000</translation>
    </message>
    <message>
        <source>Re&amp;load</source>
        <translation>Re&amp;load</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>&amp;Close</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <source>Clear list</source>
        <translation>Clear list</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <source>&amp;Debug View</source>
        <translation>&amp;Debug View</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>&amp;Overlays</translation>
    </message>
    <message>
        <source>Frame &amp;All (F)</source>
        <translation>Frame &amp;All (F)</translation>
    </message>
    <message>
        <source>Frame &amp;Selection (Shift+F)</source>
        <translation>Frame &amp;Selection (Shift+F)</translation>
    </message>
    <message>
        <source>&amp;Fly Mode (WASD, Q/E)</source>
        <translation>&amp;Fly Mode (WASD, Q/E)</translation>
    </message>
    <message>
        <source>glTF &amp;Cameras</source>
        <translation>glTF &amp;Cameras</translation>
    </message>
    <message>
        <source>&amp;Docks</source>
        <translation>&amp;Docks</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Reset Layout</translation>
    </message>
    <message>
        <source>&amp;Culling</source>
        <translation>&amp;Culling</translation>
    </message>
    <message>
        <source>&amp;Freeze Culling Camera</source>
        <translation>&amp;Freeze Culling Camera</translation>
    </message>
    <message>
        <source>&amp;Colour Boxes by Result</source>
        <translation>&amp;Colour Boxes by Result</translation>
    </message>
    <message>
        <source>&amp;Method</source>
        <translation>&amp;Method</translation>
    </message>
    <message>
        <source>Bounding sphere</source>
        <translation>Bounding sphere</translation>
    </message>
    <message>
        <source>P-vertex (AABB)</source>
        <translation>P-vertex (AABB)</translation>
    </message>
    <message>
        <source>Exact (SAT)</source>
        <translation>Exact (SAT)</translation>
    </message>
    <message>
        <source>&amp;Path</source>
        <translation>&amp;Path</translation>
    </message>
    <message>
        <source>CPU</source>
        <translation>CPU</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Settings</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Language</translation>
    </message>
    <message>
        <source>&amp;Texture Quality</source>
        <translation>&amp;Texture Quality</translation>
    </message>
    <message>
        <source>Fast</source>
        <translation>Fast</translation>
    </message>
    <message>
        <source>Balanced</source>
        <translation>Balanced</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>Best</translation>
    </message>
    <message>
        <source>Texture Cache &amp;Directory…</source>
        <translation>Texture Cache &amp;Directory…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <source>&amp;About Sherpa</source>
        <translation>&amp;About Sherpa</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>About &amp;Qt</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>Main Toolbar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <source>none (Vulkan unavailable)</source>
        <translation>none (Vulkan unavailable)</translation>
    </message>
    <message>
        <source>About Sherpa</source>
        <translation>About Sherpa</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Sherpa %1&lt;/h3&gt;&lt;p&gt;A glTF 2.0 scene inspection editor.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;Vulkan devices: %4&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sherpa %1&lt;/h3&gt;&lt;p&gt;A glTF 2.0 scene inspection editor.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;Vulkan devices: %4&lt;/p&gt;</translation>
    </message>
    <message>
        <source>GPU (compute shader, indirect draws)</source>
        <translation>GPU (compute shader, indirect draws)</translation>
    </message>
    <message>
        <source>&amp;Missing Textures as Checker</source>
        <translation>&amp;Missing Textures as Checker</translation>
    </message>
    <message>
        <source>Draw material slots whose image is missing or undecodable as a magenta/black checker (colour slots); off: the glTF defaults (white, flat normal)</source>
        <translation>Draw material slots whose image is missing or undecodable as a magenta/black checker (colour slots); off: the glTF defaults (white, flat normal)</translation>
    </message>
    <message>
        <source>&amp;UV Checker Density (checks per UV unit)</source>
        <translation>&amp;UV Checker Density (checks per UV unit)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MaterialDock</name>
    <message>
        <source>Material SSBO</source>
        <translation>Material SSBO</translation>
    </message>
    <message>
        <source>No material selected.</source>
        <translation>No material selected.</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>(unnamed)</translation>
    </message>
    <message>
        <source>Material %1 %2: 80-byte std430 record read back from the GPU material buffer at offset %3.</source>
        <translation>Material %1 %2: 80-byte std430 record read back from the GPU material buffer at offset %3.</translation>
    </message>
    <message>
        <source>Material %1 %2: the importer&apos;s CPU record (no renderer attached, so texture fields hold glTF texture indices, not bindless slots).</source>
        <translation>Material %1 %2: the importer&apos;s CPU record (no renderer attached, so texture fields hold glTF texture indices, not bindless slots).</translation>
    </message>
    <message>
        <source>⚠ Not drawn: %1. Sherpa does not implement %2, so this material is shown without %2.</source>
        <translation>⚠ Not drawn: %1. Sherpa does not implement %2, so this material is shown without %2.</translation>
    </message>
    <message>
        <source>this extension</source>
        <translation>this extension</translation>
    </message>
    <message>
        <source>these extensions</source>
        <translation>these extensions</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MaterialFieldsModel</name>
    <message>
        <source>absent</source>
        <translation>absent</translation>
    </message>
    <message>
        <source>texture %1</source>
        <translation>texture %1</translation>
    </message>
    <message>
        <source>bufferView %1</source>
        <translation>bufferView %1</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>generated</translation>
    </message>
    <message>
        <source> → image %1 (%2)</source>
        <translation> → image %1 (%2)</translation>
    </message>
    <message>
        <source> → cache: %1</source>
        <translation> → cache: %1</translation>
    </message>
    <message>
        <source>Double-click to show this texture in the texture dock</source>
        <translation>Double-click to show this texture in the texture dock</translation>
    </message>
    <message>
        <source>none (0x%1)</source>
        <translation>none (0x%1)</translation>
    </message>
    <message>
        <source>default texture</source>
        <translation>default texture</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Field</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <source>glTF property</source>
        <translation>glTF property</translation>
    </message>
    <message>
        <source>Texture chain</source>
        <translation>Texture chain</translation>
    </message>
    <message>
        <source>Byte offset in the record</source>
        <translation>Byte offset in the record</translation>
    </message>
    <message>
        <source>transmission %1, volume %2, diffuse transmission %3, dispersion %4</source>
        <translation>transmission %1, volume %2, diffuse transmission %3, dispersion %4</translation>
    </message>
    <message>
        <source> (distance infinite: none)</source>
        <translation> (distance infinite: none)</translation>
    </message>
    <message>
        <source>ior %1, specular %2, clearcoat %3, sheen %4</source>
        <translation>ior %1, specular %2, clearcoat %3, sheen %4</translation>
    </message>
    <message>
        <source>anisotropy %1, iridescence %2</source>
        <translation>anisotropy %1, iridescence %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MeshDock</name>
    <message>
        <source>max %1°, mean %2°, %3 handedness flips</source>
        <translation>max %1°, mean %2°, %3 handedness flips</translation>
    </message>
    <message>
        <source>Mesh Attributes</source>
        <translation>Mesh Attributes</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>Vertices</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>Triangles</translation>
    </message>
    <message>
        <source>Jump to vertex</source>
        <translation>Jump to vertex</translation>
    </message>
    <message>
        <source>Compare tangents</source>
        <translation>Compare tangents</translation>
    </message>
    <message>
        <source>Regenerate MikkTSpace tangents and show the angle to the mesh&apos;s tangents per vertex (sortable column)</source>
        <translation>Regenerate MikkTSpace tangents and show the angle to the mesh&apos;s tangents per vertex (sortable column)</translation>
    </message>
    <message>
        <source>No primitive selected. Select a node or primitive in the scene tree or click an object in the viewport.</source>
        <translation>No primitive selected. Select a node or primitive in the scene tree or click an object in the viewport.</translation>
    </message>
    <message>
        <source> (unwelded for flat normals)</source>
        <translation> (unwelded for flat normals)</translation>
    </message>
    <message>
        <source>Comparing…</source>
        <translation>Comparing…</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>Segments</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <source>%1 line segments</source>
        <translation>%1 line segments</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 points</translation>
    </message>
    <message>
        <source>%1 triangles</source>
        <translation>%1 triangles</translation>
    </message>
    <message>
        <source>Mesh %1 primitive %2 &quot;%3&quot;: %4 vertices (file: %5), %6, material %7, %8 on the GPU%9</source>
        <translation>Mesh %1 primitive %2 &quot;%3&quot;: %4 vertices (file: %5), %6, material %7, %8 on the GPU%9</translation>
    </message>
    <message>
        <source>; %1 %2: %3 → %4 decoded in %5 ms</source>
        <translation>; %1 %2: %3 → %4 decoded in %5 ms</translation>
    </message>
    <message>
        <source>Instances (%1)</source>
        <translation>Instances (%1)</translation>
    </message>
    <message>
        <source>Instances</source>
        <translation>Instances</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MorphWeightsPanel</name>
    <message>
        <source>No morph targets in this scene.</source>
        <translation>No morph targets in this scene.</translation>
    </message>
    <message>
        <source>Override mesh %1</source>
        <translation>Override mesh %1</translation>
    </message>
    <message>
        <source>Override %1</source>
        <translation>Override %1</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>target %1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MotionController</name>
    <message>
        <source>At %1 s: %2</source>
        <translation>At %1 s: %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ReloadController</name>
    <message>
        <source>When the File &amp;Changes</source>
        <translation>When the File &amp;Changes</translation>
    </message>
    <message>
        <source>&amp;Offer to Reload</source>
        <translation>&amp;Offer to Reload</translation>
    </message>
    <message>
        <source>&amp;Reload Automatically</source>
        <translation>&amp;Reload Automatically</translation>
    </message>
    <message>
        <source>The open file, its buffers and its images are watched on disk</source>
        <translation>The open file, its buffers and its images are watched on disk</translation>
    </message>
    <message>
        <source>%1 changed on disk: reloading.</source>
        <translation>%1 changed on disk: reloading.</translation>
    </message>
    <message>
        <source>%1 changed on disk.</source>
        <translation>%1 changed on disk.</translation>
    </message>
    <message>
        <source>%1 changed on disk. Reload the scene?</source>
        <translation>%1 changed on disk. Reload the scene?</translation>
    </message>
    <message>
        <source>File changed</source>
        <translation>File changed</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>&amp;Reload</translation>
    </message>
    <message>
        <source>&amp;Keep the Loaded Scene</source>
        <translation>&amp;Keep the Loaded Scene</translation>
    </message>
    <message>
        <source>Settings › When the File Changes › Reload Automatically reloads without asking.</source>
        <translation>Settings › When the File Changes › Reload Automatically reloads without asking.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::RenderController</name>
    <message>
        <source>No Vulkan instance: the viewport cannot render.</source>
        <translation>No Vulkan instance: the viewport cannot render.</translation>
    </message>
    <message>
        <source>Rendering on %1 (renderer ready in %2 ms).</source>
        <translation>Rendering on %1 (renderer ready in %2 ms).</translation>
    </message>
    <message>
        <source>The renderer could not start: %1</source>
        <translation>The renderer could not start: %1</translation>
    </message>
    <message>
        <source>Rendering stopped: %1</source>
        <translation>Rendering stopped: %1</translation>
    </message>
    <message>
        <source>GPU culling failed: %1</source>
        <translation>GPU culling failed: %1</translation>
    </message>
    <message>
        <source>Ray tracing is off (--rt off): no acceleration structures.</source>
        <translation>Ray tracing is off (--rt off): no acceleration structures.</translation>
    </message>
    <message>
        <source>The device does not ray trace: no acceleration structures.</source>
        <translation>The device does not ray trace: no acceleration structures.</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>No scene.</translation>
    </message>
    <message>
        <source>The scene has no triangles: no acceleration structures.</source>
        <translation>The scene has no triangles: no acceleration structures.</translation>
    </message>
    <message>
        <source>first frame %1 ms (makes the pipelines)</source>
        <translation>first frame %1 ms (makes the pipelines)</translation>
    </message>
    <message>
        <source>%1 fps, %2 ms per frame</source>
        <translation>%1 fps, %2 ms per frame</translation>
    </message>
    <message>
        <source> (GPU %1 ms)</source>
        <translation> (GPU %1 ms)</translation>
    </message>
    <message>
        <source>, resolution %1%</source>
        <translation>, resolution %1%</translation>
    </message>
    <message>
        <source>, path traced %1 spp</source>
        <translation>, path traced %1 spp</translation>
    </message>
    <message>
        <source>, estimated error %1%</source>
        <translation>, estimated error %1%</translation>
    </message>
    <message>
        <source>Mean of the last %1 frames, not counting the renderer&apos;s first (pipeline creation). While the camera moves or an animation plays on a slow device, frames are drawn at a lower resolution and without shadows to keep %2 fps; at rest or paused the full frame follows.</source>
        <translation>Mean of the last %1 frames, not counting the renderer&apos;s first (pipeline creation). While the camera moves or an animation plays on a slow device, frames are drawn at a lower resolution and without shadows to keep %2 fps; at rest or paused the full frame follows.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SceneTreeDock</name>
    <message>
        <source>Scene Tree</source>
        <translation>Scene Tree</translation>
    </message>
    <message>
        <source>Filter by name…</source>
        <translation>Filter by name…</translation>
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
        <translation>Scene %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>Node %1</translation>
    </message>
    <message>
        <source>Primitive %1</source>
        <translation>Primitive %1</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>Material %1</translation>
    </message>
    <message>
        <source>Light %1</source>
        <translation>Light %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Camera %1</translation>
    </message>
    <message>
        <source>displayed</source>
        <translation>displayed</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>matrix</translation>
    </message>
    <message>
        <source>T %1  R %2  S %3</source>
        <translation>T %1  R %2  S %3</translation>
    </message>
    <message>
        <source>skipped: %1</source>
        <translation>skipped: %1</translation>
    </message>
    <message>
        <source>%1, %2 vertices, %3 triangles</source>
        <translation>%1, %2 vertices, %3 triangles</translation>
    </message>
    <message>
        <source>directional</source>
        <translation>directional</translation>
    </message>
    <message>
        <source>point</source>
        <translation>point</translation>
    </message>
    <message>
        <source>spot</source>
        <translation>spot</translation>
    </message>
    <message>
        <source>perspective</source>
        <translation>perspective</translation>
    </message>
    <message>
        <source>orthographic</source>
        <translation>orthographic</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>scene</translation>
    </message>
    <message>
        <source>node</source>
        <translation>node</translation>
    </message>
    <message>
        <source>primitive</source>
        <translation>primitive</translation>
    </message>
    <message>
        <source>material</source>
        <translation>material</translation>
    </message>
    <message>
        <source>light</source>
        <translation>light</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>camera</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <source>Scene %1: %2</source>
        <translation>Scene %1: %2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>T %1</translation>
    </message>
    <message>
        <source>rotated</source>
        <translation>rotated</translation>
    </message>
    <message>
        <source>S %1</source>
        <translation>S %1</translation>
    </message>
    <message>
        <source>identity</source>
        <translation>identity</translation>
    </message>
    <message>
        <source>%1 vertices, %2 triangles</source>
        <translation>%1 vertices, %2 triangles</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>joint</translation>
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
        <translation>Channel %1</translation>
    </message>
    <message>
        <source>Sampler %1</source>
        <translation>Sampler %1</translation>
    </message>
    <message>
        <source>skin</source>
        <translation>skin</translation>
    </message>
    <message>
        <source>animation</source>
        <translation>animation</translation>
    </message>
    <message>
        <source>channel</source>
        <translation>channel</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>sampler</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 joints</translation>
    </message>
    <message>
        <source>%1, skeleton %2</source>
        <translation>%1, skeleton %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>node %1</translation>
    </message>
    <message>
        <source>%1 s, %2 channels</source>
        <translation>%1 s, %2 channels</translation>
    </message>
    <message>
        <source>%1, %2 samplers, %3 keys, %4 to %5 s</source>
        <translation>%1, %2 samplers, %3 keys, %4 to %5 s</translation>
    </message>
    <message>
        <source>%1 %2, sampler %3</source>
        <translation>%1 %2, sampler %3</translation>
    </message>
    <message>
        <source>%1, %2 keys</source>
        <translation>%1, %2 keys</translation>
    </message>
    <message>
        <source>%1, %2 to %3 s</source>
        <translation>%1, %2 to %3 s</translation>
    </message>
    <message>
        <source>×%1 GPU instances</source>
        <translation>×%1 GPU instances</translation>
    </message>
    <message>
        <source>×%1 GPU instances (of %2 rows)</source>
        <translation>×%1 GPU instances (of %2 rows)</translation>
    </message>
    <message>
        <source>Validation messages name this (see the Validation dock).</source>
        <translation>Validation messages name this (see the Validation dock).</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SelectionController</name>
    <message>
        <source>node %1</source>
        <translation>node %1</translation>
    </message>
    <message>
        <source>primitive %1</source>
        <translation>primitive %1</translation>
    </message>
    <message>
        <source>accessor %1: %2 of primitive %3</source>
        <translation>accessor %1: %2 of primitive %3</translation>
    </message>
    <message>
        <source>triangle %1</source>
        <translation>triangle %1</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>vertex %1</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>material %1</translation>
    </message>
    <message>
        <source>texture %1</source>
        <translation>texture %1</translation>
    </message>
    <message>
        <source>→ nothing the editor can select (%1).</source>
        <translation>→ nothing the editor can select (%1).</translation>
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
        <translation>Texture Cache</translation>
    </message>
    <message>
        <source>Recompress selected</source>
        <translation>Recompress selected</translation>
    </message>
    <message>
        <source>Clear cache</source>
        <translation>Clear cache</translation>
    </message>
    <message>
        <source>Open cache folder</source>
        <translation>Open cache folder</translation>
    </message>
    <message>
        <source>no renderer</source>
        <translation>no renderer</translation>
    </message>
    <message>
        <source>%1 textures, %2 encoded on disk, %3 on the GPU, thumbnails decoded in %4 ms</source>
        <translation>%1 textures, %2 encoded on disk, %3 on the GPU, thumbnails decoded in %4 ms</translation>
    </message>
    <message>
        <source>Delete the selected texture&apos;s cache files and load the scene again, which compresses it anew with the current quality</source>
        <translation>Delete the selected texture&apos;s cache files and load the scene again, which compresses it anew with the current quality</translation>
    </message>
    <message>
        <source>Delete every KTX2 file in the texture cache directory</source>
        <translation>Delete every KTX2 file in the texture cache directory</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TextureTableModel</name>
    <message>
        <source>Texture %1</source>
        <translation>Texture %1</translation>
    </message>
    <message>
        <source>no image</source>
        <translation>no image</translation>
    </message>
    <message>
        <source>bufferView %1</source>
        <translation>bufferView %1</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>generated</translation>
    </message>
    <message>
        <source>undecodable</source>
        <translation>undecodable</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>Texture</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Source</translation>
    </message>
    <message>
        <source>Content hash</source>
        <translation>Content hash</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Role</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Size</translation>
    </message>
    <message>
        <source>Mips</source>
        <translation>Mips</translation>
    </message>
    <message>
        <source>Disk bytes</source>
        <translation>Disk bytes</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU bytes</translation>
    </message>
    <message>
        <source>Decode ms</source>
        <translation>Decode ms</translation>
    </message>
    <message>
        <source>Encode ms</source>
        <translation>Encode ms</translation>
    </message>
    <message>
        <source>PSNR</source>
        <translation>PSNR</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>failed</translation>
    </message>
    <message>
        <source>hit</source>
        <translation>hit</translation>
    </message>
    <message>
        <source>miss</source>
        <translation>miss</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>stale</translation>
    </message>
    <message>
        <source>recompressed</source>
        <translation>recompressed</translation>
    </message>
    <message>
        <source>fallback</source>
        <translation>fallback</translation>
    </message>
    <message>
        <source>missing: %1</source>
        <translation>missing: %1</translation>
    </message>
    <message>
        <source>Container</source>
        <translation>Container</translation>
    </message>
    <message>
        <source>State</source>
        <translation>State</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>Timeline</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Speed</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Loop</translation>
    </message>
    <message>
        <source>Scrub; the ticks are the animation&apos;s key times</source>
        <translation>Scrub; the ticks are the animation&apos;s key times</translation>
    </message>
    <message>
        <source>No animation</source>
        <translation>No animation</translation>
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
        <translation>Play</translation>
    </message>
    <message>
        <source>no animation</source>
        <translation>no animation</translation>
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
        <translation>vertex 0</translation>
    </message>
    <message>
        <source>vertex 1</source>
        <translation>vertex 1</translation>
    </message>
    <message>
        <source>vertex 2</source>
        <translation>vertex 2</translation>
    </message>
    <message>
        <source>area</source>
        <translation>area</translation>
    </message>
    <message>
        <source>length</source>
        <translation>length</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ValidationDock</name>
    <message>
        <source>Validation</source>
        <translation>Validation</translation>
    </message>
    <message>
        <source>Filter by code, pointer or text…</source>
        <translation>Filter by code, pointer or text…</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>No scene.</translation>
    </message>
    <message>
        <source>No messages: nothing to report about this file.</source>
        <translation>No messages: nothing to report about this file.</translation>
    </message>
    <message>
        <source>%1 errors, %2 warnings, %3 information, %4 hints. Click a message to select what it names.</source>
        <translation>%1 errors, %2 warnings, %3 information, %4 hints. Click a message to select what it names.</translation>
    </message>
    <message>
        <source>The list is truncated.</source>
        <translation>The list is truncated.</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ValidationModel</name>
    <message>
        <source>Errors (%1)</source>
        <translation>Errors (%1)</translation>
    </message>
    <message>
        <source>Warnings (%1)</source>
        <translation>Warnings (%1)</translation>
    </message>
    <message>
        <source>Information (%1)</source>
        <translation>Information (%1)</translation>
    </message>
    <message>
        <source>Hints (%1)</source>
        <translation>Hints (%1)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>(the whole file)</source>
        <translation>(the whole file)</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>Message</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::VariantMenu</name>
    <message>
        <source>default materials</source>
        <translation>default materials</translation>
    </message>
    <message>
        <source>Material variant: %1 (%2 primitive(s), %3 draw(s) changed material; %4 GPU bytes uploaded%5; nothing reloaded).</source>
        <translation>Material variant: %1 (%2 primitive(s), %3 draw(s) changed material; %4 GPU bytes uploaded%5; nothing reloaded).</translation>
    </message>
    <message>
        <source>, culling lists rebuilt for a changed alpha mode</source>
        <translation>, culling lists rebuilt for a changed alpha mode</translation>
    </message>
    <message>
        <source>Va&amp;riants</source>
        <translation>Va&amp;riants</translation>
    </message>
    <message>
        <source>&amp;Default Materials</source>
        <translation>&amp;Default Materials</translation>
    </message>
    <message>
        <source>The file has no material variants</source>
        <translation>The file has no material variants</translation>
    </message>
    <message>
        <source>; ray tracer: %1 geometry record(s), %2 bytes</source>
        <translation>; ray tracer: %1 geometry record(s), %2 bytes</translation>
    </message>
    <message>
        <source>, TLAS rebuilt: any-hit forced on %1 BLAS built opaque, back-face culling off on %2</source>
        <translation>, TLAS rebuilt: any-hit forced on %1 BLAS built opaque, back-face culling off on %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::VertexTableModel</name>
    <message>
        <source>tangent error (deg)</source>
        <translation>tangent error (deg)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ViewController</name>
    <message>
        <source>View: %1</source>
        <translation>View: %1</translation>
    </message>
    <message>
        <source>Overlays</source>
        <translation>Overlays</translation>
    </message>
    <message>
        <source>Overlays (%1)</source>
        <translation>Overlays (%1)</translation>
    </message>
    <message>
        <source>Overlays: none shown</source>
        <translation>Overlays: none shown</translation>
    </message>
    <message>
        <source>Overlays: %1</source>
        <translation>Overlays: %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <source>the room</source>
        <translation>the room</translation>
    </message>
    <message>
        <source>Environment: %1.</source>
        <translation>Environment: %1.</translation>
    </message>
    <message>
        <source>Shadows: %1 cascades, %2 PCF taps; the viewport&apos;s maps stay %3x%3 texels (fixed when its renderer is made), not %4</source>
        <translation>Shadows: %1 cascades, %2 PCF taps; the viewport&apos;s maps stay %3x%3 texels (fixed when its renderer is made), not %4</translation>
    </message>
    <message>
        <source>(the scene has no cameras)</source>
        <translation>(the scene has no cameras)</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>Camera %1</translation>
    </message>
</context>
</TS>
