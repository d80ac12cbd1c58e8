<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>Format</name>
    <message>
        <source>%1 B</source>
        <translation>%1 字节</translation>
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
        <translation>未知 (%1)</translation>
    </message>
    <message>
        <source>authored</source>
        <translation>文件提供</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>生成</translation>
    </message>
    <message>
        <source>defaulted</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>colour (sRGB)</source>
        <translation>颜色 (sRGB)</translation>
    </message>
    <message>
        <source>linear data</source>
        <translation>线性数据</translation>
    </message>
    <message>
        <source>normal map</source>
        <translation>法线贴图</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>未使用</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
</context>
<context>
    <name>LabChart</name>
    <message>
        <source>time (%1)</source>
        <translation>时间（%1）</translation>
    </message>
    <message>
        <source>Pareto front</source>
        <translation>帕累托前沿</translation>
    </message>
    <message>
        <source>%1 (in use)</source>
        <translation>%1（使用中）</translation>
    </message>
</context>
<context>
    <name>ViewCatalog</name>
    <message>
        <source>Lit</source>
        <translation>光照</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>法线</translation>
    </message>
    <message>
        <source>Tangents</source>
        <translation>切线</translation>
    </message>
    <message>
        <source>Bitangents</source>
        <translation>副切线</translation>
    </message>
    <message>
        <source>Handedness (tangent w)</source>
        <translation>手性 (切线 w)</translation>
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
        <translation>UV 0 棋盘格</translation>
    </message>
    <message>
        <source>UV 1 checker</source>
        <translation>UV 1 棋盘格</translation>
    </message>
    <message>
        <source>Base colour</source>
        <translation>基础颜色</translation>
    </message>
    <message>
        <source>Metallic</source>
        <translation>金属度</translation>
    </message>
    <message>
        <source>Roughness</source>
        <translation>粗糙度</translation>
    </message>
    <message>
        <source>Occlusion</source>
        <translation>遮蔽</translation>
    </message>
    <message>
        <source>Emissive</source>
        <translation>自发光</translation>
    </message>
    <message>
        <source>Geometric vs shading normal</source>
        <translation>几何法线与着色法线之差</translation>
    </message>
    <message>
        <source>Tangent provenance</source>
        <translation>切线来源</translation>
    </message>
    <message>
        <source>Shading normal</source>
        <translation>着色法线</translation>
    </message>
    <message>
        <source>Specular (F0)</source>
        <translation>镜面反射 (F0)</translation>
    </message>
    <message>
        <source>Joint influence</source>
        <translation>关节影响</translation>
    </message>
    <message>
        <source>Wireframe</source>
        <translation>线框</translation>
    </message>
    <message>
        <source>Normal glyphs</source>
        <translation>法线箭头</translation>
    </message>
    <message>
        <source>Tangent glyphs</source>
        <translation>切线箭头</translation>
    </message>
    <message>
        <source>Bitangent glyphs</source>
        <translation>副切线箭头</translation>
    </message>
    <message>
        <source>Bounding boxes</source>
        <translation>包围盒</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>骨架</translation>
    </message>
    <message>
        <source>Sun shadow</source>
        <translation>太阳阴影</translation>
    </message>
    <message>
        <source>Ambient occlusion (rays)</source>
        <translation>环境光遮蔽（光线）</translation>
    </message>
    <message>
        <source>Shadow error (maps vs rays)</source>
        <translation>阴影误差（贴图对比光线）</translation>
    </message>
    <message>
        <source>Index of refraction</source>
        <translation>折射率</translation>
    </message>
    <message>
        <source>Specular weight</source>
        <translation>镜面反射强度</translation>
    </message>
    <message>
        <source>Specular colour</source>
        <translation>镜面反射颜色</translation>
    </message>
    <message>
        <source>Transmission</source>
        <translation>透射</translation>
    </message>
    <message>
        <source>Volume thickness</source>
        <translation>体积厚度</translation>
    </message>
    <message>
        <source>Volume attenuation</source>
        <translation>体积衰减</translation>
    </message>
    <message>
        <source>Diffuse transmission</source>
        <translation>漫透射</translation>
    </message>
    <message>
        <source>Clearcoat</source>
        <translation>清漆</translation>
    </message>
    <message>
        <source>Clearcoat roughness</source>
        <translation>清漆粗糙度</translation>
    </message>
    <message>
        <source>Clearcoat normal</source>
        <translation>清漆法线</translation>
    </message>
    <message>
        <source>Sheen colour</source>
        <translation>光泽层颜色</translation>
    </message>
    <message>
        <source>Sheen roughness</source>
        <translation>光泽层粗糙度</translation>
    </message>
    <message>
        <source>Anisotropy strength</source>
        <translation>各向异性强度</translation>
    </message>
    <message>
        <source>Anisotropy direction</source>
        <translation>各向异性方向</translation>
    </message>
    <message>
        <source>Iridescence</source>
        <translation>虹彩</translation>
    </message>
    <message>
        <source>Iridescence thickness</source>
        <translation>虹彩膜厚</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AccelerationDock</name>
    <message>
        <source>Acceleration Structures</source>
        <translation>加速结构</translation>
    </message>
    <message>
        <source>%1 BLAS, %2 triangles, %3 built, %4 compacted (%5%), %6 batches, built in %7 ms</source>
        <translation>%1 个 BLAS，%2 个三角形，构建 %3，压缩后 %4（%5%），%6 批，构建用时 %7 ms</translation>
    </message>
    <message>
        <source>TLAS: %1 instances of %2 node/mesh pairs, %3 deduplicated, %4 mirrored, %5 hidden, %6 non-finite; %7</source>
        <translation>TLAS：%2 个节点/网格对中的 %1 个实例，%3 个去重，%4 个镜像，%5 个隐藏，%6 个非有限；%7</translation>
    </message>
    <message>
        <source>Total on the GPU: %1 (scratch buffer %2)</source>
        <translation>GPU 上共计：%1（暂存缓冲区 %2）</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AccelerationModel</name>
    <message>
        <source>%1 geometries (one per triangle primitive), %2 of them opaque (no any-hit)</source>
        <translation>%1 个几何体（每个三角形图元一个），其中 %2 个不透明（无 any-hit）</translation>
    </message>
    <message>
        <source>mesh %1</source>
        <translation>网格 %1</translation>
    </message>
    <message>
        <source>Geometries (opaque)</source>
        <translation>几何体（不透明）</translation>
    </message>
    <message>
        <source>Mesh</source>
        <translation>网格</translation>
    </message>
    <message>
        <source>Geometries</source>
        <translation>几何体</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>三角形</translation>
    </message>
    <message>
        <source>Build ms</source>
        <translation>构建 ms</translation>
    </message>
    <message>
        <source>Built</source>
        <translation>构建</translation>
    </message>
    <message>
        <source>Compacted</source>
        <translation>压缩后</translation>
    </message>
    <message>
        <source>Scratch</source>
        <translation>暂存</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::AttributeModel</name>
    <message>
        <source>indices</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>authored</source>
        <translation>文件提供</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>生成</translation>
    </message>
    <message>
        <source>not uploaded</source>
        <translation>未上传</translation>
    </message>
    <message>
        <source>yes (%1 values)</source>
        <translation>是 (%1 个值)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 (stride %2)</source>
        <translation>%1 (步长 %2)</translation>
    </message>
    <message>
        <source>Attribute</source>
        <translation>属性</translation>
    </message>
    <message>
        <source>Provenance</source>
        <translation>来源</translation>
    </message>
    <message>
        <source>Accessor</source>
        <translation>访问器</translation>
    </message>
    <message>
        <source>Normalized</source>
        <translation>归一化</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>数量</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>最小值</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>最大值</translation>
    </message>
    <message>
        <source>Sparse</source>
        <translation>稀疏</translation>
    </message>
    <message>
        <source>Buffer view</source>
        <translation>缓冲视图</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU 字节</translation>
    </message>
    <message>
        <source>, normalized</source>
        <translation>，归一化</translation>
    </message>
    <message>
        <source>Component</source>
        <translation>分量</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CommandLine</name>
    <message>
        <source>First frame of the scene %1 ms after launch.</source>
        <translation>启动后 %1 毫秒显示场景的第一帧。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CompareController</name>
    <message>
        <source>Compare with glTF scene</source>
        <translation>与 glTF 场景比较</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb);;All files (*)</source>
        <translation>glTF 场景 (*.gltf *.glb);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Side B: %1 could not be loaded: %2</source>
        <translation>B 侧：无法加载 %1：%2</translation>
    </message>
    <message>
        <source>Side B: %1 loaded.</source>
        <translation>B 侧：已加载 %1。</translation>
    </message>
    <message>
        <source>Side B: loading %1…</source>
        <translation>B 侧：正在加载 %1…</translation>
    </message>
    <message>
        <source>%1, source textures</source>
        <translation>%1，源纹理</translation>
    </message>
    <message>
        <source>Side B: loading %1 with tangents by %2…</source>
        <translation>B 侧：正在以 %2 切线加载 %1…</translation>
    </message>
    <message>
        <source>%1, tangents: %2</source>
        <translation>%1，切线：%2</translation>
    </message>
    <message>
        <source>Side A&apos;s tangents: %1 primitive(s) authored, %2 exact MikkTSpace, %3 none (no TANGENT, no normal texture: there B differs from no tangents).</source>
        <translation>A 侧切线：%1 个图元来自文件，%2 个为精确 MikkTSpace，%3 个没有（无 TANGENT、无法线纹理：此处 B 与无切线相比）。</translation>
    </message>
    <message>
        <source>Overlays and the selection highlight are drawn in the Raster mode only.</source>
        <translation>叠加层和选择高亮仅在光栅化模式下绘制。</translation>
    </message>
    <message>
        <source>The ray tracer cannot draw this frame: %1. Back to Raster.</source>
        <translation>光线追踪器无法绘制此画面：%1。已切回光栅化。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CompareControls</name>
    <message>
        <source>Raster</source>
        <translation>光栅化</translation>
    </message>
    <message>
        <source>Ray traced</source>
        <translation>光线追踪</translation>
    </message>
    <message>
        <source>Split (A | B)</source>
        <translation>分屏（A | B）</translation>
    </message>
    <message>
        <source>Difference (heat map)</source>
        <translation>差异（热图）</translation>
    </message>
    <message>
        <source>Viewport &amp;Mode</source>
        <translation>视口模式(&amp;M)</translation>
    </message>
    <message>
        <source>Compare &amp;With (side B)</source>
        <translation>比较对象（B 侧）(&amp;W)</translation>
    </message>
    <message>
        <source>Another Debug View</source>
        <translation>其他调试视图</translation>
    </message>
    <message>
        <source>The Ray Tracer</source>
        <translation>光线追踪器</translation>
    </message>
    <message>
        <source>Another File…</source>
        <translation>其他文件…</translation>
    </message>
    <message>
        <source>Another File… (%1)</source>
        <translation>其他文件…（%1）</translation>
    </message>
    <message>
        <source>Viewport: %1</source>
        <translation>视口：%1</translation>
    </message>
    <message>
        <source>Raster or ray traced frame, or side A (this view, rasterized) against side B with one camera. Split: drag the divider line (or Ctrl+drag anywhere) to move it.</source>
        <translation>光栅化或光线追踪的画面，或以同一相机比较 A 侧（此视图，光栅化）与 B 侧。分屏：拖动分隔线（或在任意位置 Ctrl+拖动）来移动它。</translation>
    </message>
    <message>
        <source>ray tracer</source>
        <translation>光线追踪器</translation>
    </message>
    <message>
        <source>no file</source>
        <translation>无文件</translation>
    </message>
    <message>
        <source>B: %1</source>
        <translation>B：%1</translation>
    </message>
    <message>
        <source>This File, Source Textures (no BC7/BC5)</source>
        <translation>此文件，源纹理（无 BC7/BC5）</translation>
    </message>
    <message>
        <source>The rasterizer: every view, overlays and the selection</source>
        <translation>光栅化器：所有视图、叠加层和选择</translation>
    </message>
    <message>
        <source>Primary rays through the acceleration structures: the surface-data views</source>
        <translation>穿过加速结构的主光线：表面数据视图</translation>
    </message>
    <message>
        <source>Side A left, side B right, one camera: drag the divider line (or Ctrl+drag anywhere) to move it</source>
        <translation>A 侧在左，B 侧在右，同一相机：拖动分隔线（或在任意位置 Ctrl+拖动）来移动它</translation>
    </message>
    <message>
        <source>Heat map of |A − B| with its legend: mean, max, PSNR, % of pixels over the threshold</source>
        <translation>|A − B| 的热图及图例：平均值、最大值、PSNR、超过阈值的像素百分比</translation>
    </message>
    <message>
        <source>Difference &amp;Heat Scale</source>
        <translation>差异热图刻度(&amp;H)</translation>
    </message>
    <message>
        <source>Difference &amp;Threshold</source>
        <translation>差异阈值(&amp;T)</translation>
    </message>
    <message>
        <source>%1/255 and above at full heat</source>
        <translation>%1/255 及以上为最热</translation>
    </message>
    <message>
        <source>Automatic (99.9th percentile of the differences)</source>
        <translation>自动（差异的第 99.9 百分位）</translation>
    </message>
    <message>
        <source>Over %1/255</source>
        <translation>超过 %1/255</translation>
    </message>
    <message>
        <source>MikkTSpace, exact (vertices split per corner)</source>
        <translation>MikkTSpace，精确（按角点拆分顶点）</translation>
    </message>
    <message>
        <source>MikkTSpace, welded (last corner per vertex)</source>
        <translation>MikkTSpace，焊接（每个顶点取最后一个角点）</translation>
    </message>
    <message>
        <source>Lengyel (summed per vertex)</source>
        <translation>Lengyel（按顶点求和）</translation>
    </message>
    <message>
        <source>This File, Tangents Regenerated By</source>
        <translation>此文件，切线重新生成方法</translation>
    </message>
    <message>
        <source>What side B of the comparison draws: %1</source>
        <translation>对比的 B 侧绘制的内容：%1</translation>
    </message>
    <message>
        <source>Side B is shown in the Split and Difference modes (Viewport button); choosing it here switches to Split. Now: %1</source>
        <translation>B 侧在分屏和差异模式中显示（视口按钮）；在此选择会切换到分屏。当前：%1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::CullingDock</name>
    <message>
        <source>Culling Statistics</source>
        <translation>剔除统计</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>总数</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>可见</translation>
    </message>
    <message>
        <source>Culled</source>
        <translation>已剔除</translation>
    </message>
    <message>
        <source>False positives</source>
        <translation>误判可见</translation>
    </message>
    <message>
        <source>Draw calls</source>
        <translation>绘制调用</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>三角形</translation>
    </message>
    <message>
        <source>CPU cull ms</source>
        <translation>CPU 剔除 ms</translation>
    </message>
    <message>
        <source>GPU cull ms</source>
        <translation>GPU 剔除 ms</translation>
    </message>
    <message>
        <source>Hidden</source>
        <translation>隐藏</translation>
    </message>
    <message>
        <source>visible</source>
        <translation>可见</translation>
    </message>
    <message>
        <source>culled</source>
        <translation>已剔除</translation>
    </message>
    <message>
        <source>update</source>
        <translation>更新</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>没有场景。</translation>
    </message>
    <message>
        <source>Pass &quot;%1&quot;: method %2, %3%4</source>
        <translation>通道“%1”：方法 %2，%3%4</translation>
    </message>
    <message>
        <source>, culling camera frozen</source>
        <translation>，剔除相机已冻结</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: GPU path off (Culling › Path › GPU)</source>
        <translation>CPU/GPU 一致性：GPU 路径已关闭（剔除 › 路径 › GPU）</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: ✔ both keep %1 of %2</source>
        <translation>CPU/GPU 一致性：✔ 两者均保留 %2 个中的 %1 个</translation>
    </message>
    <message>
        <source>CPU/GPU agreement: ✘ %1 objects differ (CPU keeps %2, GPU %3)</source>
        <translation>CPU/GPU 一致性：✘ %1 个对象不一致（CPU 保留 %2 个，GPU %3 个）</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>Renderer passes: none (culling off or no frame yet)</source>
        <translation>渲染器通道：无（剔除已关闭或尚无帧）</translation>
    </message>
    <message>
        <source>Renderer passes, last frame (cascades reused from the frame that drew them)</source>
        <translation>渲染器通道，上一帧（级联沿用绘制它们的那一帧）</translation>
    </message>
    <message>
        <source>Renderer passes, last frame</source>
        <translation>渲染器通道，上一帧</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::DifferenceLegend</name>
    <message>
        <source>|A − B|, largest of R, G, B (of 255)</source>
        <translation>|A − B|，R、G、B 中的最大值（满值 255）</translation>
    </message>
    <message>
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <source>No frame compared yet.</source>
        <translation>尚未比较任何画面。</translation>
    </message>
    <message>
        <source>∞ (identical)</source>
        <translation>∞（完全相同）</translation>
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
        <translation>平均 %1
最大 %2
PSNR %3
%5 个像素中 %4% 超过 %6</translation>
    </message>
    <message>
        <source>≥ %1 (auto)</source>
        <translation>≥ %1（自动）</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::EnvironmentMenu</name>
    <message>
        <source>&amp;Environment</source>
        <translation>环境(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;None (Ambient Only)</source>
        <translation>无（仅环境光项）(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Room (Built In)</source>
        <translation>房间（内置）(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Open HDR or EXR… (%1)</source>
        <translation>打开 HDR 或 EXR…(%1)(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Open HDR or EXR…</source>
        <translation>打开 HDR 或 EXR…(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Background</source>
        <translation>背景(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Blurred</source>
        <translation>模糊(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Solid Colour</source>
        <translation>纯色(&amp;S)</translation>
    </message>
    <message>
        <source>Rotate −15° (now %1°)</source>
        <translation>旋转 −15°（当前 %1°）</translation>
    </message>
    <message>
        <source>Rotate +15° (now %1°)</source>
        <translation>旋转 +15°（当前 %1°）</translation>
    </message>
    <message>
        <source>Brighter (intensity %1)</source>
        <translation>更亮（强度 %1）</translation>
    </message>
    <message>
        <source>Darker</source>
        <translation>更暗</translation>
    </message>
    <message>
        <source>Reset Rotation and Intensity</source>
        <translation>重置旋转和强度</translation>
    </message>
    <message>
        <source>Default &amp;Sun</source>
        <translation>默认太阳(&amp;S)</translation>
    </message>
    <message>
        <source>Energy &amp;Compensation (Multiple Scattering)</source>
        <translation>能量补偿（多次散射）(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Tone Mapping</source>
        <translation>色调映射(&amp;T)</translation>
    </message>
    <message>
        <source>Khronos PBR &amp;Neutral</source>
        <translation>Khronos PBR 中性(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;ACES Filmic</source>
        <translation>ACES 电影(&amp;A)</translation>
    </message>
    <message>
        <source>A&amp;gX</source>
        <translation>AgX(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;Linear (Clamp)</source>
        <translation>线性（截断）(&amp;L)</translation>
    </message>
    <message>
        <source>Exposure +½ Stop (now %1 EV)</source>
        <translation>曝光 +½ 档（当前 %1 EV）</translation>
    </message>
    <message>
        <source>Exposure −½ Stop</source>
        <translation>曝光 −½ 档</translation>
    </message>
    <message>
        <source>Exposure 0 EV</source>
        <translation>曝光 0 EV</translation>
    </message>
    <message>
        <source>Open Environment</source>
        <translation>打开环境</translation>
    </message>
    <message>
        <source>HDR images (*.hdr *.exr);;All files (*)</source>
        <translation>HDR 图像 (*.hdr *.exr);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::InstanceTableModel</name>
    <message>
        <source>Row</source>
        <translation>行</translation>
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
        <translation>警告：%1</translation>
    </message>
    <message>
        <source>The Lab could not run: %1</source>
        <translation>实验室无法运行：%1</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>已取消。</translation>
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
        <translation>实验室</translation>
    </message>
    <message>
        <source>Methods</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Budget</source>
        <translation>预算</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Compute budget</source>
        <translation>计算预算</translation>
    </message>
    <message>
        <source>Numbers</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Failures</source>
        <translation>失败</translation>
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
        <translation>要在已加载场景上测量的方法族</translation>
    </message>
    <message>
        <source>Measure every method of the family on this scene, off the UI thread</source>
        <translation>在界面线程之外，于此场景上测量该族的每种方法</translation>
    </message>
    <message>
        <source>The numbers, as sherpa-cli lab --csv writes them</source>
        <translation>数值，与 sherpa-cli lab --csv 的输出相同</translation>
    </message>
    <message>
        <source>The chart, as sherpa-cli lab --chart writes it</source>
        <translation>图表，与 sherpa-cli lab --chart 的输出相同</translation>
    </message>
    <message>
        <source>The chart as shown</source>
        <translation>按显示的图表</translation>
    </message>
    <message>
        <source>Pick a family and run it on %1.</source>
        <translation>选择一个方法族并在 %1 上运行。</translation>
    </message>
    <message>
        <source>Open a scene to measure its methods.</source>
        <translation>打开场景以测量其方法。</translation>
    </message>
    <message>
        <source>Compute the budget of %1.</source>
        <translation>计算 %1 的预算。</translation>
    </message>
    <message>
        <source>Open a scene to compute its budget.</source>
        <translation>打开场景以计算其预算。</translation>
    </message>
    <message>
        <source>Running %1 on %2…</source>
        <translation>正在 %2 上运行 %1…</translation>
    </message>
    <message>
        <source>Computing the budget of %1…</source>
        <translation>正在计算 %1 的预算…</translation>
    </message>
    <message>
        <source>%1 against %2; time in %3</source>
        <translation>%1 对比 %2；时间单位 %3</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>无法写入 %1。</translation>
    </message>
    <message>
        <source>Export the Lab report</source>
        <translation>导出实验室报告</translation>
    </message>
    <message>
        <source>The line joins the Pareto front; the method in use is ringed.</source>
        <translation>折线连接帕累托前沿；正在使用的方法带圆圈标记。</translation>
    </message>
    <message>
        <source>Click a point (or double-click a row) to use that method in the viewport: culling methods, and the cascade count and PCF taps of a shadow setting (the viewport&apos;s shadow maps keep their resolution, fixed when its renderer is made). Tangent and texture methods are measured here but the viewport has no switch for them, so clicking them changes nothing.</source>
        <translation>点击一个点（或双击一行）即在视口中使用该方法：剔除方法，以及阴影设置的级联数和 PCF 采样数（视口的阴影贴图保持其分辨率，该分辨率在创建其渲染器时确定）。切线和纹理方法在此测量，但视口没有对应开关，点击它们不会改变任何内容。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LabTableModel</name>
    <message>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Time (%1)</source>
        <translation>时间（%1）</translation>
    </message>
    <message>
        <source>Failures</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>未运行</translation>
    </message>
    <message>
        <source>Cause</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>数量</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU 字节</translation>
    </message>
    <message>
        <source>Unified</source>
        <translation>统一布局</translation>
    </message>
    <message>
        <source>Stored</source>
        <translation>实际存储</translation>
    </message>
    <message>
        <source>Needed</source>
        <translation>所需</translation>
    </message>
    <message>
        <source>Oversized texture</source>
        <translation>过大的纹理</translation>
    </message>
    <message>
        <source>%1×%2: %3 texels per pixel at best, 1/%4 per side would look the same</source>
        <translation>%1×%2：最多每像素 %3 个纹素，每边缩小到 1/%4 看起来相同</translation>
    </message>
    <message>
        <source>Unread attribute</source>
        <translation>未读取的属性</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>发现</translation>
    </message>
    <message>
        <source>Detail</source>
        <translation>详情</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LoadController</name>
    <message>
        <source>Loading %1 cancelled; the result is discarded.</source>
        <translation>已取消加载 %1；结果将被丢弃。</translation>
    </message>
    <message>
        <source>Texture cache directory</source>
        <translation>纹理缓存目录</translation>
    </message>
    <message>
        <source>Loading %1…</source>
        <translation>正在加载 %1…</translation>
    </message>
    <message>
        <source>1/4 parsing…</source>
        <translation>1/4 解析…</translation>
    </message>
    <message>
        <source>2/4 geometry…</source>
        <translation>2/4 几何…</translation>
    </message>
    <message>
        <source>3/4 tangents: mesh %1 of %2</source>
        <translation>3/4 切线：网格 %1 / %2</translation>
    </message>
    <message>
        <source>4/4 textures: %1 of %2</source>
        <translation>4/4 纹理：%1 / %2</translation>
    </message>
    <message>
        <source>Loaded %1 in %2 ms (engine %3 ms, thumbnails %4 ms, textures %5 ms).</source>
        <translation>已加载 %1，用时 %2 毫秒（引擎 %3 毫秒，缩略图 %4 毫秒，纹理 %5 毫秒）。</translation>
    </message>
    <message>
        <source>The file places %1 camera(s): View › glTF Cameras looks through them; the automatic view looks from the side of the first.</source>
        <translation>文件放置了 %1 个相机：视图 › glTF 相机 可通过它们观看；自动视图从第一个相机所在的一侧观看。</translation>
    </message>
    <message>
        <source>Could not load %1; the current scene is kept.</source>
        <translation>无法加载 %1；保留当前场景。</translation>
    </message>
    <message>
        <source>Could not load %1; no scene is open.</source>
        <translation>无法加载 %1；当前没有打开的场景。</translation>
    </message>
    <message>
        <source>Load failed</source>
        <translation>加载失败</translation>
    </message>
    <message>
        <source>Could not load %1:
%2

The current scene is kept.</source>
        <translation>无法加载 %1：
%2

保留当前场景。</translation>
    </message>
    <message>
        <source>Could not load %1:
%2

No scene is open.</source>
        <translation>无法加载 %1：
%2

当前没有打开的场景。</translation>
    </message>
    <message>
        <source>(no recent files)</source>
        <translation>（没有最近文件）</translation>
    </message>
    <message>
        <source>Open glTF scene</source>
        <translation>打开 glTF 场景</translation>
    </message>
    <message>
        <source>glTF scenes (*.gltf *.glb);;All files (*)</source>
        <translation>glTF 场景 (*.gltf *.glb);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Texture cache cleared: %1 files deleted from %2; the next load compresses again.</source>
        <translation>纹理缓存已清空：已从 %2 删除 %1 个文件；下次加载时将重新压缩。</translation>
    </message>
    <message>
        <source>Texture %1: %2 cache files deleted; reloading to compress it again.</source>
        <translation>纹理 %1：已删除 %2 个缓存文件；正在重新加载以重新压缩。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::LogDock</name>
    <message>
        <source>Log</source>
        <translation>日志</translation>
    </message>
    <message>
        <source>info</source>
        <translation>信息</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MainWindow</name>
    <message>
        <source>No scene. Open a glTF file or a built-in scene from the File menu.</source>
        <translation>没有场景。请通过“文件”菜单打开 glTF 文件或内置场景。</translation>
    </message>
    <message>
        <source>Sherpa</source>
        <translation>Sherpa</translation>
    </message>
    <message>
        <source>%1: %2 nodes, %3 primitives, %4 instances, %5 materials, %6 textures</source>
        <translation>%1：%2 个节点，%3 个图元，%4 个实例，%5 个材质，%6 个纹理</translation>
    </message>
    <message>
        <source>%1 — Sherpa</source>
        <translation>%1 — Sherpa</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Built-in Scenes</source>
        <translation>内置场景(&amp;B)</translation>
    </message>
    <message>
        <source>Default scene</source>
        <translation>默认场景</translation>
    </message>
    <message>
        <source>Grid, 10 × 10</source>
        <translation>网格，10 × 10</translation>
    </message>
    <message>
        <source>Grid, 100 × 100</source>
        <translation>网格，100 × 100</translation>
    </message>
    <message>
        <source>Grid, 1000 × 1000</source>
        <translation>网格，1000 × 1000</translation>
    </message>
    <message>
        <source>Re&amp;load</source>
        <translation>重新加载(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>关闭(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>Clear list</source>
        <translation>清空列表</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Debug View</source>
        <translation>调试视图(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>叠加层(&amp;O)</translation>
    </message>
    <message>
        <source>Frame &amp;All (F)</source>
        <translation>全部框选(&amp;A) (F)</translation>
    </message>
    <message>
        <source>Frame &amp;Selection (Shift+F)</source>
        <translation>框选所选(&amp;S) (Shift+F)</translation>
    </message>
    <message>
        <source>&amp;Fly Mode (WASD, Q/E)</source>
        <translation>飞行模式(&amp;F) (WASD, Q/E)</translation>
    </message>
    <message>
        <source>glTF &amp;Cameras</source>
        <translation>glTF 相机(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Docks</source>
        <translation>停靠面板(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>重置布局(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Culling</source>
        <translation>剔除(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Freeze Culling Camera</source>
        <translation>冻结剔除相机(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Colour Boxes by Result</source>
        <translation>按结果为包围盒着色(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Method</source>
        <translation>方法(&amp;M)</translation>
    </message>
    <message>
        <source>Bounding sphere</source>
        <translation>包围球</translation>
    </message>
    <message>
        <source>P-vertex (AABB)</source>
        <translation>P 顶点 (AABB)</translation>
    </message>
    <message>
        <source>Exact (SAT)</source>
        <translation>精确 (SAT)</translation>
    </message>
    <message>
        <source>&amp;Path</source>
        <translation>路径(&amp;P)</translation>
    </message>
    <message>
        <source>CPU</source>
        <translation>CPU</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>设置(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Texture Quality</source>
        <translation>纹理质量(&amp;T)</translation>
    </message>
    <message>
        <source>Fast</source>
        <translation>快速</translation>
    </message>
    <message>
        <source>Balanced</source>
        <translation>均衡</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>最佳</translation>
    </message>
    <message>
        <source>Texture Cache &amp;Directory…</source>
        <translation>纹理缓存目录(&amp;D)…</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About Sherpa</source>
        <translation>关于 Sherpa(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <source>Main Toolbar</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>none (Vulkan unavailable)</source>
        <translation>无（Vulkan 不可用）</translation>
    </message>
    <message>
        <source>About Sherpa</source>
        <translation>关于 Sherpa</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Sherpa %1&lt;/h3&gt;&lt;p&gt;A glTF 2.0 scene inspection editor.&lt;/p&gt;&lt;p&gt;Qt %2 (built with %3)&lt;br&gt;Vulkan devices: %4&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sherpa %1&lt;/h3&gt;&lt;p&gt;glTF 2.0 场景检查编辑器。&lt;/p&gt;&lt;p&gt;Qt %2（构建时为 %3）&lt;br&gt;Vulkan 设备：%4&lt;/p&gt;</translation>
    </message>
    <message>
        <source>GPU (compute shader, indirect draws)</source>
        <translation>GPU（计算着色器，间接绘制）</translation>
    </message>
    <message>
        <source>&amp;Missing Textures as Checker</source>
        <translation>缺失纹理显示为棋盘格(&amp;M)</translation>
    </message>
    <message>
        <source>Draw material slots whose image is missing or undecodable as a magenta/black checker (colour slots); off: the glTF defaults (white, flat normal)</source>
        <translation>将图像缺失或无法解码的材质槽绘制为品红/黑色棋盘格(颜色槽);关闭时使用 glTF 默认值(白色、平坦法线)</translation>
    </message>
    <message>
        <source>&amp;UV Checker Density (checks per UV unit)</source>
        <translation>UV 棋盘格密度（每 UV 单位格数）(&amp;U)</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MaterialDock</name>
    <message>
        <source>Material SSBO</source>
        <translation>材质 SSBO</translation>
    </message>
    <message>
        <source>No material selected.</source>
        <translation>未选择材质。</translation>
    </message>
    <message>
        <source>(unnamed)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <source>Material %1 %2: 80-byte std430 record read back from the GPU material buffer at offset %3.</source>
        <translation>材质 %1 %2：从 GPU 材质缓冲区偏移 %3 处读回的 80 字节 std430 记录。</translation>
    </message>
    <message>
        <source>Material %1 %2: the importer&apos;s CPU record (no renderer attached, so texture fields hold glTF texture indices, not bindless slots).</source>
        <translation>材质 %1 %2：导入器的 CPU 记录（未连接渲染器，因此纹理字段是 glTF 纹理索引，而非无绑定槽位）。</translation>
    </message>
    <message>
        <source>⚠ Not drawn: %1. Sherpa does not implement %2, so this material is shown without %2.</source>
        <translation>⚠ 未绘制：%1。Sherpa 未实现%2，因此此材质显示时不含%2。</translation>
    </message>
    <message>
        <source>this extension</source>
        <translation>该扩展</translation>
    </message>
    <message>
        <source>these extensions</source>
        <translation>这些扩展</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MaterialFieldsModel</name>
    <message>
        <source>absent</source>
        <translation>无</translation>
    </message>
    <message>
        <source>texture %1</source>
        <translation>纹理 %1</translation>
    </message>
    <message>
        <source>bufferView %1</source>
        <translation>bufferView %1</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>生成</translation>
    </message>
    <message>
        <source> → image %1 (%2)</source>
        <translation> → 图像 %1 (%2)</translation>
    </message>
    <message>
        <source> → cache: %1</source>
        <translation> → 缓存：%1</translation>
    </message>
    <message>
        <source>Double-click to show this texture in the texture dock</source>
        <translation>双击在纹理面板中显示此纹理</translation>
    </message>
    <message>
        <source>none (0x%1)</source>
        <translation>无 (0x%1)</translation>
    </message>
    <message>
        <source>default texture</source>
        <translation>默认纹理</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>偏移</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>字段</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>glTF property</source>
        <translation>glTF 属性</translation>
    </message>
    <message>
        <source>Texture chain</source>
        <translation>纹理链</translation>
    </message>
    <message>
        <source>Byte offset in the record</source>
        <translation>记录中的字节偏移</translation>
    </message>
    <message>
        <source>transmission %1, volume %2, diffuse transmission %3, dispersion %4</source>
        <translation>透射 %1，体积 %2，漫透射 %3，色散 %4</translation>
    </message>
    <message>
        <source> (distance infinite: none)</source>
        <translation>（距离无限：无衰减）</translation>
    </message>
    <message>
        <source>ior %1, specular %2, clearcoat %3, sheen %4</source>
        <translation>ior %1, specular %2, clearcoat %3, sheen %4</translation>
    </message>
    <message>
        <source>anisotropy %1, iridescence %2</source>
        <translation>各向异性 %1，虹彩 %2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MeshDock</name>
    <message>
        <source>max %1°, mean %2°, %3 handedness flips</source>
        <translation>最大 %1°，平均 %2°，%3 处手性翻转</translation>
    </message>
    <message>
        <source>Mesh Attributes</source>
        <translation>网格属性</translation>
    </message>
    <message>
        <source>Vertices</source>
        <translation>顶点</translation>
    </message>
    <message>
        <source>Triangles</source>
        <translation>三角形</translation>
    </message>
    <message>
        <source>Jump to vertex</source>
        <translation>跳转到顶点</translation>
    </message>
    <message>
        <source>Compare tangents</source>
        <translation>比较切线</translation>
    </message>
    <message>
        <source>Regenerate MikkTSpace tangents and show the angle to the mesh&apos;s tangents per vertex (sortable column)</source>
        <translation>重新生成 MikkTSpace 切线，并逐顶点显示与网格切线的夹角（可排序列）</translation>
    </message>
    <message>
        <source>No primitive selected. Select a node or primitive in the scene tree or click an object in the viewport.</source>
        <translation>未选择图元。请在场景树中选择节点或图元，或在视口中单击物体。</translation>
    </message>
    <message>
        <source> (unwelded for flat normals)</source>
        <translation>（为平面法线拆分顶点）</translation>
    </message>
    <message>
        <source>Comparing…</source>
        <translation>正在比较…</translation>
    </message>
    <message>
        <source>Segments</source>
        <translation>线段</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点</translation>
    </message>
    <message>
        <source>%1 line segments</source>
        <translation>%1 条线段</translation>
    </message>
    <message>
        <source>%1 points</source>
        <translation>%1 个点</translation>
    </message>
    <message>
        <source>%1 triangles</source>
        <translation>%1 个三角形</translation>
    </message>
    <message>
        <source>Mesh %1 primitive %2 &quot;%3&quot;: %4 vertices (file: %5), %6, material %7, %8 on the GPU%9</source>
        <translation>网格 %1 图元 %2“%3”：%4 个顶点（文件中 %5 个），%6，材质 %7，GPU 上 %8%9</translation>
    </message>
    <message>
        <source>; %1 %2: %3 → %4 decoded in %5 ms</source>
        <translation>；%1 %2：%3 → %4，解码 %5 ms</translation>
    </message>
    <message>
        <source>Instances (%1)</source>
        <translation>实例 (%1)</translation>
    </message>
    <message>
        <source>Instances</source>
        <translation>实例</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MorphWeightsPanel</name>
    <message>
        <source>No morph targets in this scene.</source>
        <translation>此场景没有变形目标。</translation>
    </message>
    <message>
        <source>Override mesh %1</source>
        <translation>覆盖网格 %1</translation>
    </message>
    <message>
        <source>Override %1</source>
        <translation>覆盖 %1</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>目标 %1</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::MotionController</name>
    <message>
        <source>At %1 s: %2</source>
        <translation>在 %1 秒：%2</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ReloadController</name>
    <message>
        <source>When the File &amp;Changes</source>
        <translation>文件更改时(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Offer to Reload</source>
        <translation>提示重新加载(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Reload Automatically</source>
        <translation>自动重新加载(&amp;R)</translation>
    </message>
    <message>
        <source>The open file, its buffers and its images are watched on disk</source>
        <translation>监视磁盘上打开的文件及其缓冲区和图像</translation>
    </message>
    <message>
        <source>%1 changed on disk: reloading.</source>
        <translation>%1 已在磁盘上更改：正在重新加载。</translation>
    </message>
    <message>
        <source>%1 changed on disk.</source>
        <translation>%1 已在磁盘上更改。</translation>
    </message>
    <message>
        <source>%1 changed on disk. Reload the scene?</source>
        <translation>%1 已在磁盘上更改。重新加载场景？</translation>
    </message>
    <message>
        <source>File changed</source>
        <translation>文件已更改</translation>
    </message>
    <message>
        <source>&amp;Reload</source>
        <translation>重新加载(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Keep the Loaded Scene</source>
        <translation>保留已加载的场景(&amp;K)</translation>
    </message>
    <message>
        <source>Settings › When the File Changes › Reload Automatically reloads without asking.</source>
        <translation>设置 › 文件更改时 › 自动重新加载：不询问直接重新加载。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::RenderController</name>
    <message>
        <source>No Vulkan instance: the viewport cannot render.</source>
        <translation>没有 Vulkan 实例：视口无法渲染。</translation>
    </message>
    <message>
        <source>Rendering on %1 (renderer ready in %2 ms).</source>
        <translation>在 %1 上渲染（渲染器 %2 ms 后就绪）。</translation>
    </message>
    <message>
        <source>The renderer could not start: %1</source>
        <translation>渲染器无法启动：%1</translation>
    </message>
    <message>
        <source>Rendering stopped: %1</source>
        <translation>渲染已停止：%1</translation>
    </message>
    <message>
        <source>GPU culling failed: %1</source>
        <translation>GPU 剔除失败：%1</translation>
    </message>
    <message>
        <source>Ray tracing is off (--rt off): no acceleration structures.</source>
        <translation>光线追踪已关闭（--rt off）：没有加速结构。</translation>
    </message>
    <message>
        <source>The device does not ray trace: no acceleration structures.</source>
        <translation>该设备不支持光线追踪：没有加速结构。</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>没有场景。</translation>
    </message>
    <message>
        <source>The scene has no triangles: no acceleration structures.</source>
        <translation>场景没有三角形：没有加速结构。</translation>
    </message>
    <message>
        <source>first frame %1 ms (makes the pipelines)</source>
        <translation>首帧 %1 毫秒（创建管线）</translation>
    </message>
    <message>
        <source>%1 fps, %2 ms per frame</source>
        <translation>%1 fps，每帧 %2 毫秒</translation>
    </message>
    <message>
        <source> (GPU %1 ms)</source>
        <translation>（GPU %1 毫秒）</translation>
    </message>
    <message>
        <source>, resolution %1%</source>
        <translation>，分辨率 %1%</translation>
    </message>
    <message>
        <source>, path traced %1 spp</source>
        <translation>，路径追踪 %1 spp</translation>
    </message>
    <message>
        <source>, estimated error %1%</source>
        <translation>，估计误差 %1%</translation>
    </message>
    <message>
        <source>Mean of the last %1 frames, not counting the renderer&apos;s first (pipeline creation). While the camera moves or an animation plays on a slow device, frames are drawn at a lower resolution and without shadows to keep %2 fps; at rest or paused the full frame follows.</source>
        <translation>最近 %1 帧的平均值，不计渲染器的第一帧（创建管线）。在慢速设备上移动相机或播放动画时，以较低分辨率且不带阴影绘制以保持 %2 fps；静止或暂停后显示完整画面。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SceneTreeDock</name>
    <message>
        <source>Scene Tree</source>
        <translation>场景树</translation>
    </message>
    <message>
        <source>Filter by name…</source>
        <translation>按名称筛选…</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SceneTreeModel</name>
    <message>
        <source>Scene %1</source>
        <translation>场景 %1</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>Primitive %1</source>
        <translation>图元 %1</translation>
    </message>
    <message>
        <source>Material %1</source>
        <translation>材质 %1</translation>
    </message>
    <message>
        <source>Light %1</source>
        <translation>灯光 %1</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>相机 %1</translation>
    </message>
    <message>
        <source>displayed</source>
        <translation>显示中</translation>
    </message>
    <message>
        <source>matrix</source>
        <translation>矩阵</translation>
    </message>
    <message>
        <source>T %1  R %2  S %3</source>
        <translation>平移 %1  旋转 %2  缩放 %3</translation>
    </message>
    <message>
        <source>skipped: %1</source>
        <translation>已跳过：%1</translation>
    </message>
    <message>
        <source>%1, %2 vertices, %3 triangles</source>
        <translation>%1，%2 个顶点，%3 个三角形</translation>
    </message>
    <message>
        <source>directional</source>
        <translation>平行光</translation>
    </message>
    <message>
        <source>point</source>
        <translation>点光源</translation>
    </message>
    <message>
        <source>spot</source>
        <translation>聚光灯</translation>
    </message>
    <message>
        <source>perspective</source>
        <translation>透视</translation>
    </message>
    <message>
        <source>orthographic</source>
        <translation>正交</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>node</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>primitive</source>
        <translation>图元</translation>
    </message>
    <message>
        <source>material</source>
        <translation>材质</translation>
    </message>
    <message>
        <source>light</source>
        <translation>灯光</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>详情</translation>
    </message>
    <message>
        <source>Scene %1: %2</source>
        <translation>场景 %1：%2</translation>
    </message>
    <message>
        <source>T %1</source>
        <translation>平移 %1</translation>
    </message>
    <message>
        <source>rotated</source>
        <translation>已旋转</translation>
    </message>
    <message>
        <source>S %1</source>
        <translation>缩放 %1</translation>
    </message>
    <message>
        <source>identity</source>
        <translation>单位变换</translation>
    </message>
    <message>
        <source>%1 vertices, %2 triangles</source>
        <translation>%1 个顶点，%2 个三角形</translation>
    </message>
    <message>
        <source>joint</source>
        <translation>关节</translation>
    </message>
    <message>
        <source>Skin %1</source>
        <translation>蒙皮 %1</translation>
    </message>
    <message>
        <source>Skin %1: %2</source>
        <translation>蒙皮 %1: %2</translation>
    </message>
    <message>
        <source>Animation %1</source>
        <translation>动画 %1</translation>
    </message>
    <message>
        <source>Animation %1: %2</source>
        <translation>动画 %1: %2</translation>
    </message>
    <message>
        <source>Channel %1</source>
        <translation>通道 %1</translation>
    </message>
    <message>
        <source>Sampler %1</source>
        <translation>采样器 %1</translation>
    </message>
    <message>
        <source>skin</source>
        <translation>蒙皮</translation>
    </message>
    <message>
        <source>animation</source>
        <translation>动画</translation>
    </message>
    <message>
        <source>channel</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>sampler</source>
        <translation>采样器</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 个关节</translation>
    </message>
    <message>
        <source>%1, skeleton %2</source>
        <translation>%1，骨架 %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>%1 s, %2 channels</source>
        <translation>%1 秒，%2 个通道</translation>
    </message>
    <message>
        <source>%1, %2 samplers, %3 keys, %4 to %5 s</source>
        <translation>%1，%2 个采样器，%3 个关键帧，%4 至 %5 秒</translation>
    </message>
    <message>
        <source>%1 %2, sampler %3</source>
        <translation>%1 %2，采样器 %3</translation>
    </message>
    <message>
        <source>%1, %2 keys</source>
        <translation>%1，%2 个关键帧</translation>
    </message>
    <message>
        <source>%1, %2 to %3 s</source>
        <translation>%1，%2 至 %3 秒</translation>
    </message>
    <message>
        <source>×%1 GPU instances</source>
        <translation>×%1 个 GPU 实例</translation>
    </message>
    <message>
        <source>×%1 GPU instances (of %2 rows)</source>
        <translation>×%1 个 GPU 实例（共 %2 行）</translation>
    </message>
    <message>
        <source>Validation messages name this (see the Validation dock).</source>
        <translation>有验证消息指向此对象（见“验证”面板）。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::SelectionController</name>
    <message>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <source>primitive %1</source>
        <translation>图元 %1</translation>
    </message>
    <message>
        <source>accessor %1: %2 of primitive %3</source>
        <translation>访问器 %1：图元 %3 的 %2</translation>
    </message>
    <message>
        <source>triangle %1</source>
        <translation>三角形 %1</translation>
    </message>
    <message>
        <source>vertex %1</source>
        <translation>顶点 %1</translation>
    </message>
    <message>
        <source>material %1</source>
        <translation>材质 %1</translation>
    </message>
    <message>
        <source>texture %1</source>
        <translation>纹理 %1</translation>
    </message>
    <message>
        <source>→ nothing the editor can select (%1).</source>
        <translation>→ 编辑器中没有可选择的对象（%1）。</translation>
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
        <translation>纹理缓存</translation>
    </message>
    <message>
        <source>Recompress selected</source>
        <translation>重新压缩所选</translation>
    </message>
    <message>
        <source>Clear cache</source>
        <translation>清空缓存</translation>
    </message>
    <message>
        <source>Open cache folder</source>
        <translation>打开缓存文件夹</translation>
    </message>
    <message>
        <source>no renderer</source>
        <translation>无渲染器</translation>
    </message>
    <message>
        <source>%1 textures, %2 encoded on disk, %3 on the GPU, thumbnails decoded in %4 ms</source>
        <translation>%1 个纹理，磁盘上编码数据 %2，GPU 上 %3，缩略图解码用时 %4 ms</translation>
    </message>
    <message>
        <source>Delete the selected texture&apos;s cache files and load the scene again, which compresses it anew with the current quality</source>
        <translation>删除所选纹理的缓存文件并重新加载场景，以当前质量重新压缩该纹理</translation>
    </message>
    <message>
        <source>Delete every KTX2 file in the texture cache directory</source>
        <translation>删除纹理缓存目录中的所有 KTX2 文件</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TextureTableModel</name>
    <message>
        <source>Texture %1</source>
        <translation>纹理 %1</translation>
    </message>
    <message>
        <source>no image</source>
        <translation>无图像</translation>
    </message>
    <message>
        <source>bufferView %1</source>
        <translation>bufferView %1</translation>
    </message>
    <message>
        <source>generated</source>
        <translation>生成</translation>
    </message>
    <message>
        <source>undecodable</source>
        <translation>无法解码</translation>
    </message>
    <message>
        <source>Texture</source>
        <translation>纹理</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <source>Content hash</source>
        <translation>内容哈希</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>用途</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>格式</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>尺寸</translation>
    </message>
    <message>
        <source>Mips</source>
        <translation>Mip 层级</translation>
    </message>
    <message>
        <source>Disk bytes</source>
        <translation>磁盘字节</translation>
    </message>
    <message>
        <source>GPU bytes</source>
        <translation>GPU 字节</translation>
    </message>
    <message>
        <source>Decode ms</source>
        <translation>解码 ms</translation>
    </message>
    <message>
        <source>Encode ms</source>
        <translation>编码 ms</translation>
    </message>
    <message>
        <source>PSNR</source>
        <translation>PSNR</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>hit</source>
        <translation>命中</translation>
    </message>
    <message>
        <source>miss</source>
        <translation>未命中</translation>
    </message>
    <message>
        <source>stale</source>
        <translation>过期</translation>
    </message>
    <message>
        <source>recompressed</source>
        <translation>已重新压缩</translation>
    </message>
    <message>
        <source>fallback</source>
        <translation>回退（RGBA8）</translation>
    </message>
    <message>
        <source>missing: %1</source>
        <translation>缺失:%1</translation>
    </message>
    <message>
        <source>Container</source>
        <translation>容器</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>时间轴</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>循环</translation>
    </message>
    <message>
        <source>Scrub; the ticks are the animation&apos;s key times</source>
        <translation>拖动定位；刻度为动画的关键帧时间</translation>
    </message>
    <message>
        <source>No animation</source>
        <translation>无动画</translation>
    </message>
    <message>
        <source>Animation %1</source>
        <translation>动画 %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>no animation</source>
        <translation>无动画</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 秒</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::TriangleTableModel</name>
    <message>
        <source>vertex 0</source>
        <translation>顶点 0</translation>
    </message>
    <message>
        <source>vertex 1</source>
        <translation>顶点 1</translation>
    </message>
    <message>
        <source>vertex 2</source>
        <translation>顶点 2</translation>
    </message>
    <message>
        <source>area</source>
        <translation>面积</translation>
    </message>
    <message>
        <source>length</source>
        <translation>长度</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ValidationDock</name>
    <message>
        <source>Validation</source>
        <translation>验证</translation>
    </message>
    <message>
        <source>Filter by code, pointer or text…</source>
        <translation>按代码、指针或文本筛选…</translation>
    </message>
    <message>
        <source>No scene.</source>
        <translation>没有场景。</translation>
    </message>
    <message>
        <source>No messages: nothing to report about this file.</source>
        <translation>没有消息：此文件没有需要报告的问题。</translation>
    </message>
    <message>
        <source>%1 errors, %2 warnings, %3 information, %4 hints. Click a message to select what it names.</source>
        <translation>%1 个错误，%2 个警告，%3 条信息，%4 条提示。点击消息可选中它所指的对象。</translation>
    </message>
    <message>
        <source>The list is truncated.</source>
        <translation>列表已截断。</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ValidationModel</name>
    <message>
        <source>Errors (%1)</source>
        <translation>错误（%1）</translation>
    </message>
    <message>
        <source>Warnings (%1)</source>
        <translation>警告（%1）</translation>
    </message>
    <message>
        <source>Information (%1)</source>
        <translation>信息（%1）</translation>
    </message>
    <message>
        <source>Hints (%1)</source>
        <translation>提示（%1）</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>(the whole file)</source>
        <translation>（整个文件）</translation>
    </message>
    <message>
        <source>Message</source>
        <translation>消息</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::VariantMenu</name>
    <message>
        <source>default materials</source>
        <translation>默认材质</translation>
    </message>
    <message>
        <source>Material variant: %1 (%2 primitive(s), %3 draw(s) changed material; %4 GPU bytes uploaded%5; nothing reloaded).</source>
        <translation>材质变体：%1（%2 个图元、%3 次绘制更换了材质；上传 %4 字节 GPU 数据%5；未重新加载）。</translation>
    </message>
    <message>
        <source>, culling lists rebuilt for a changed alpha mode</source>
        <translation>，因 Alpha 模式改变而重建剔除列表</translation>
    </message>
    <message>
        <source>Va&amp;riants</source>
        <translation>变体(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Default Materials</source>
        <translation>默认材质(&amp;D)</translation>
    </message>
    <message>
        <source>The file has no material variants</source>
        <translation>该文件没有材质变体</translation>
    </message>
    <message>
        <source>; ray tracer: %1 geometry record(s), %2 bytes</source>
        <translation>；光线追踪器：%1 条几何记录，%2 字节</translation>
    </message>
    <message>
        <source>, TLAS rebuilt: any-hit forced on %1 BLAS built opaque, back-face culling off on %2</source>
        <translation>，TLAS 已重建：对 %1 个按不透明构建的 BLAS 强制执行 any-hit，对 %2 个关闭背面剔除</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::VertexTableModel</name>
    <message>
        <source>tangent error (deg)</source>
        <translation>切线误差（度）</translation>
    </message>
</context>
<context>
    <name>sherpa::editor::ViewController</name>
    <message>
        <source>View: %1</source>
        <translation>视图：%1</translation>
    </message>
    <message>
        <source>Overlays</source>
        <translation>叠加层</translation>
    </message>
    <message>
        <source>Overlays (%1)</source>
        <translation>叠加层（%1）</translation>
    </message>
    <message>
        <source>Overlays: none shown</source>
        <translation>叠加层：未显示</translation>
    </message>
    <message>
        <source>Overlays: %1</source>
        <translation>叠加层：%1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>the room</source>
        <translation>房间</translation>
    </message>
    <message>
        <source>Environment: %1.</source>
        <translation>环境：%1。</translation>
    </message>
    <message>
        <source>Shadows: %1 cascades, %2 PCF taps; the viewport&apos;s maps stay %3x%3 texels (fixed when its renderer is made), not %4</source>
        <translation>阴影：%1 个级联，%2 个 PCF 采样；视口的阴影贴图保持 %3x%3 纹素（创建其渲染器时确定），而不是 %4</translation>
    </message>
    <message>
        <source>(the scene has no cameras)</source>
        <translation>（场景中没有相机）</translation>
    </message>
    <message>
        <source>Camera %1</source>
        <translation>相机 %1</translation>
    </message>
</context>
</TS>
