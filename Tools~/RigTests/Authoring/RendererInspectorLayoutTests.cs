using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Issue 40's inspector that guides (RendererInspectorLayout, drawn by GregoryTerrainRendererEditor):
    /// which fields show in each view mode, the quality presets, the metre values of terrain-unit
    /// fields, the triangle readouts with Horizon levels and the renderer's Profiler markers. What
    /// only the editor shows (the popups, one Undo step) is not checked here.
    /// </summary>
    [TestFixture]
    public class RendererInspectorLayoutTests
    {
        static readonly InspectorContext[] Views =
        {
            new InspectorContext(TerrainViewMode.OpenWorld, true, false, false),
            new InspectorContext(TerrainViewMode.SingleRange, true, false, false),
            new InspectorContext(TerrainViewMode.Zoom, true, false, false),
        };

        static string Source(params string[] path) => File.ReadAllText(PackageRoot.Combine(path));

        static string RendererSources() => string.Concat(Directory.GetFiles(PackageRoot.Combine("Runtime"), "GregoryTerrainRenderer*.cs").OrderBy(p => p, StringComparer.Ordinal)
            .Append(PackageRoot.Combine("Runtime", "TerrainFrameDriver.cs")).Select(File.ReadAllText));

        /// <summary>
        /// The inspector before issue 40 (its DrawSettings): every field, less Cache shader and LOD
        /// camera without Compute cache and Max factor, Target pixel error and Anchor tiles with a
        /// uniform factor, whatever the view.
        /// </summary>
        static int ShownBefore(InspectorContext c) =>
            RendererInspectorLayout.Sections.Sum(s => s.fields.Length) - (c.computeCache ? 0 : 2) - (c.adaptive ? 0 : 3);

        [Test]
        public void EachViewModeShowsOnlyTheFieldsThatTakeEffect()
        {
            var table = new List<string>();
            foreach (bool cache in new[] { false, true })
                foreach (InspectorContext v in Views)
                {
                    var c = new InspectorContext(v.mode, true, cache, false);
                    table.Add($"{c.mode,-12} {(cache ? "compute cache" : "domain stage "),-14} before {ShownBefore(c),2}  after {RendererInspectorLayout.FieldsShown(c).Count,2}");
                }
            var fallback = new InspectorContext(TerrainViewMode.SingleRange, true, false, true);
            table.Add($"{"fallback",-12} {"(no tessellator)",-14} before {ShownBefore(fallback),2}  after {RendererInspectorLayout.FieldsShown(fallback).Count,2}");
            TestContext.WriteLine("fields shown (of " + RendererInspectorLayout.Sections.Sum(s => s.fields.Length) + ")\n" + string.Join("\n", table));

            List<string> open = RendererInspectorLayout.FieldsShown(Views[0]), single = RendererInspectorLayout.FieldsShown(Views[1]),
                zoom = RendererInspectorLayout.FieldsShown(Views[2]), fb = RendererInspectorLayout.FieldsShown(fallback);
            // Horizon levels ignore the range, anchoring and the vertex cache (the renderer's LevelsOn checks).
            Assert.That(open, Has.None.AnyOf("range", "anchorTiles", "vertexEvaluation", "cacheShader", "lodCamera", "fallbackGridFactor"));
            Assert.That(open, Does.Contain("tessellation.tiles").And.Contain("tessellation.targetPixels").And.Contain(RendererInspectorLayout.ViewModeField));
            Assert.That(single, Does.Contain("range").And.Contain("anchorTiles").And.Contain("vertexEvaluation"));
            Assert.That(single, Has.No.Member("fallbackGridFactor"), "a GPU that tessellates never draws the fallback grid");
            Assert.That(zoom, Has.No.Member("range"), "the Zoom Range Controller sets the range every frame");
            Assert.That(fb, Does.Contain("fallbackGridFactor").And.Contain("range"));
            Assert.That(fb, Has.None.AnyOf("tessellation.uniformFactor", "tessellation.maxFactor", "tessellation.targetPixels", "anchorTiles", "vertexEvaluation"));
            Assert.That(RendererInspectorLayout.FieldsShown(new InspectorContext(TerrainViewMode.SingleRange, true, true, false)),
                Does.Contain("cacheShader").And.Contain("lodCamera"));
            // Several renderers selected: a field shows where any of them uses it.
            Assert.That(RendererInspectorLayout.ShowsForAny("range", new[] { Views[0], Views[1] }), Is.True);
            Assert.That(RendererInspectorLayout.ShowsForAny("range", new[] { Views[0], Views[2] }), Is.False);
            foreach (InspectorContext v in Views) Assert.That(RendererInspectorLayout.FieldsShown(v).Count, Is.LessThan(ShownBefore(v)), v.mode.ToString());
            // The manual quotes these counts (index.md, "Renderer settings").
            Match quoted = Regex.Match(Source("Documentation~", "index.md"), @"of (\d+), Open world shows\s+(\d+), Single range\s+(\d+), Zoom (\d+) \((\d+) before\)");
            Assert.That(quoted.Success, "index.md no longer quotes the fields shown per view mode");
            Assert.That(Enumerable.Range(1, 5).Select(k => int.Parse(quoted.Groups[k].Value, CultureInfo.InvariantCulture)),
                Is.EqualTo(new[] { RendererInspectorLayout.Sections.Sum(s => s.fields.Length), open.Count, single.Count, zoom.Count, ShownBefore(Views[0]) }));
        }

        /// <summary>A new renderer's noise octaves: the last argument of its NoiseSettings initialiser.</summary>
        static int RendererNoiseOctaves()
        {
            Match m = Regex.Match(RendererSources(), @"NoiseSettings noise = new NoiseSettings\([^)]*,\s*(\d+)\);");
            Assert.That(m.Success, "no default for noise");
            return int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture);
        }

        static SettingField Slider(string path) => RendererInspectorLayout.Find(path) ?? throw new AssertionException($"no slider for {path}");

        [Test]
        public void PresetsAreValidOrderedAndMediumIsANewRenderer()
        {
            var presets = ((QualityPreset[])Enum.GetValues(typeof(QualityPreset))).Select(RendererInspectorLayout.Preset).ToArray();
            Assert.That(presets, Has.Length.EqualTo(4));
            for (int k = 0; k < presets.Length; k++)
            {
                QualityValues v = presets[k];
                new TessellationSettings(v.tiles, v.maxFactor, v.targetPixelError, 0f).Validate("preset");
                Assert.That(v.tiles % 2 == 0 && v.tiles >= LodLevels.MinTiles && v.tiles <= 64, $"preset {(QualityPreset)k}: tiles {v.tiles} must draw in Open world");
                Assert.That(v.noiseOctaves, Is.InRange(0, 16));
                Assert.That(v.vertexEvaluation, Is.InRange(0, 1));
                Assert.That(RendererInspectorLayout.PresetOf(v), Is.EqualTo((QualityPreset)k));
                if (k > 0)
                {
                    Assert.That(v.targetPixelError, Is.LessThan(presets[k - 1].targetPixelError), "each preset finer than the one before");
                    Assert.That(v.tiles * v.maxFactor, Is.GreaterThanOrEqualTo(presets[k - 1].tiles * presets[k - 1].maxFactor));
                }
            }
            QualityValues medium = RendererInspectorLayout.Preset(QualityPreset.Medium);
            Assert.That(RendererSources(), Does.Contain("TessellationSettings tessellation = TessellationSettings.Default;"));
            Assert.That(medium.targetPixelError, Is.EqualTo(TessellationSettings.Default.targetPixels));
            Assert.That(medium.maxFactor, Is.EqualTo(TessellationSettings.Default.maxFactor));
            Assert.That(medium.tiles, Is.EqualTo(TessellationSettings.Default.tiles));
            Assert.That(medium.noiseOctaves, Is.EqualTo(RendererNoiseOctaves()));
            Assert.That(RendererSources(), Does.Contain("VertexEvaluation vertexEvaluation = VertexEvaluation.DomainStage;"));
            Assert.That(medium.vertexEvaluation, Is.EqualTo(0));
            // Ultra reaches the manual's advice (0.5 px for a largest error of about 1 px), within the slider.
            Assert.That(Source("Documentation~", "index.md"), Does.Contain("0.5 px about 1 px"));
            Assert.That(RendererInspectorLayout.Preset(QualityPreset.Ultra).targetPixelError, Is.EqualTo(0.5f));
            Assert.That(Slider("tessellation.targetPixels").min, Is.LessThanOrEqualTo(0.5f));
            Assert.That(RendererInspectorLayout.PresetOf(new QualityValues(3f, 64f, 16, 6, 0)), Is.Null, "custom values");
            Assert.That(RendererInspectorLayout.TilesForOpenWorld(5), Is.EqualTo(8));
            Assert.That(RendererInspectorLayout.TilesForOpenWorld(17), Is.EqualTo(18));
            Assert.That(RendererInspectorLayout.TilesForOpenWorld(16), Is.EqualTo(16));
            StringAssert.Contains("preset (9)", Assert.Throws<ArgumentException>(() => RendererInspectorLayout.Preset((QualityPreset)9)).Message);
        }

        /// <summary>
        /// What a preset writes: Compute cache only where a Cache Shader is set (else the renderer
        /// warns and draws through the domain stage), and in Open world the hidden Vertex
        /// evaluation is left as it is. A preset still reads back whatever Vertex evaluation it left.
        /// </summary>
        [Test]
        public void UltraCachesOnlyWithACacheShaderAndOpenWorldKeepsVertexEvaluation()
        {
            var custom = new QualityValues(3f, 64f, 16, 6, 1);
            Assert.That(RendererInspectorLayout.PresetToWrite(QualityPreset.Ultra, custom, cacheShaderSet: true, openWorld: false).vertexEvaluation, Is.EqualTo(1));
            Assert.That(RendererInspectorLayout.PresetToWrite(QualityPreset.Ultra, custom, cacheShaderSet: false, openWorld: false).vertexEvaluation, Is.EqualTo(0));
            Assert.That(RendererInspectorLayout.PresetToWrite(QualityPreset.Low, custom, cacheShaderSet: true, openWorld: true).vertexEvaluation, Is.EqualTo(1), "Open world hides Vertex evaluation");
            Assert.That(RendererInspectorLayout.PresetToWrite(QualityPreset.Ultra, new QualityValues(3f, 64f, 16, 6, 0), true, openWorld: true).vertexEvaluation, Is.EqualTo(0));
            QualityValues ultraNoCache = RendererInspectorLayout.PresetToWrite(QualityPreset.Ultra, custom, false, false);
            Assert.That(ultraNoCache.targetPixelError, Is.EqualTo(0.5f));
            Assert.That(RendererInspectorLayout.PresetOf(ultraNoCache), Is.EqualTo(QualityPreset.Ultra));
            Assert.That(typeof(IEquatable<QualityValues>).IsAssignableFrom(typeof(QualityValues)), "struct equality without IEquatable boxes");
            Assert.That(new QualityValues(1f, 2f, 8, 4, 0).Equals(new QualityValues(1f, 2f, 8, 4, 1)), Is.False);
        }

        /// <summary>With several renderers selected the View mode is theirs only when they all share it.</summary>
        [Test]
        public void ViewModeIsMixedWhenTheSelectedRenderersDiffer()
        {
            Assert.That(RendererInspectorLayout.CommonMode(new[] { TerrainViewMode.Zoom, TerrainViewMode.Zoom }), Is.EqualTo(TerrainViewMode.Zoom));
            Assert.That(RendererInspectorLayout.CommonMode(new[] { TerrainViewMode.OpenWorld, TerrainViewMode.Zoom }), Is.Null);
            Assert.That(RendererInspectorLayout.CommonMode(new[] { TerrainViewMode.SingleRange, TerrainViewMode.SingleRange, TerrainViewMode.OpenWorld }), Is.Null);
        }

        /// <summary>A typed cell size of 0 or less is refused with a message naming the field and value.</summary>
        [Test]
        public void ANonPositiveCellSizeIsNamed()
        {
            Assert.That(RendererInspectorLayout.LengthProblem("Noise cell size (m)", 0.0), Does.Contain("Noise cell size (m)").And.Contain("0"));
            Assert.That(RendererInspectorLayout.LengthProblem("Noise cell size (m)", -2.0), Does.Contain("-2"));
            Assert.That(RendererInspectorLayout.LengthProblem("Noise cell size (m)", 0.5), Is.Null);
        }

        /// <summary>
        /// One unit: every renderer field or settings struct field whose tooltip speaks of terrain units
        /// or cells across the terrain is typed and read in metres, within the field's own slider.
        /// </summary>
        [Test]
        public void TerrainUnitFieldsAreShownInMetres()
        {
            const string TerrainUnits = "terrain (height )?units|across the whole terrain";
            var tooltipped = Regex.Matches(RendererSources(), @"\[Tooltip\(""([^""]*)""\)\]\s*\[SerializeField[^\]]*\]\s*\w+\s+(\w+)")
                .Cast<Match>().Where(m => Regex.IsMatch(m.Groups[1].Value, TerrainUnits))
                .Select(m => m.Groups[2].Value).ToList();
            foreach (var (field, fields) in RendererInspectorLayout.Structs)
                tooltipped.AddRange(fields.Where(f => Regex.IsMatch(f.tooltip, TerrainUnits)).Select(f => field + "." + f.name));
            var metres = RendererInspectorLayout.MetreFields.Select(m => m.field).ToList();
            Assert.That(tooltipped, Is.Not.Empty);
            Assert.That(tooltipped, Is.SubsetOf(metres), "a terrain-unit field without its metres in the inspector");
            foreach (var m in RendererInspectorLayout.MetreFields)
            {
                Assert.That(m.label, Does.EndWith("(m)"));
                Assert.That((m.min, m.max), Is.EqualTo((Slider(m.field).min, Slider(m.field).max)), m.field);
            }
            Assert.That(Source("Editor", "GregoryTerrainRendererEditor.cs"), Does.Contain("RendererInspectorLayout.MetreFields"));

            // 0.02 of a Height Scale of 1000 m is 20 m, of 3000 m 60 m.
            Assert.That(RendererInspectorLayout.ToMetres(TerrainLength.Height, 0.02, 1000, 1000), Is.EqualTo(20.0).Within(1e-9));
            Assert.That(RendererInspectorLayout.ToMetres(TerrainLength.Height, 0.02, 3000, 20000), Is.EqualTo(60.0).Within(1e-9));
            Assert.That(RendererInspectorLayout.ToMetres(TerrainLength.CellsAcross, 16, 3000, 20000), Is.EqualTo(1250.0));
            foreach (TerrainLength kind in new[] { TerrainLength.Height, TerrainLength.CellsAcross })
                Assert.That(RendererInspectorLayout.FromMetres(kind, RendererInspectorLayout.ToMetres(kind, 0.37, 600, 1000), 600, 1000), Is.EqualTo(0.37).Within(1e-12));
            Assert.That(RendererInspectorLayout.ClampedFromMetres(TerrainLength.Height, 900, 1000, 1000, 0f, 0.5f), Is.EqualTo(0.5f));
            Assert.That(RendererInspectorLayout.ClampedFromMetres(TerrainLength.CellsAcross, 0, 1000, 1000, 0.5f, 4096f), Is.EqualTo(4096f));
            Assert.That(RendererInspectorLayout.ClampedFromMetres(TerrainLength.CellsAcross, 1e6, 1000, 1000, 0.5f, 4096f), Is.EqualTo(0.5f));
            Assert.That(RendererInspectorLayout.ClampedFromMetres(TerrainLength.CellsAcross, 62.5, 1000, 1000, 0.5f, 4096f), Is.EqualTo(16f));
        }

        /// <summary>
        /// Camera Range Controller's View distance is typed in metres of its terrain's width; the
        /// stored part of the width is unchanged, so saved scenes keep their square (editor-only:
        /// the inspector's source and its conversion are checked here).
        /// </summary>
        [Test]
        public void ViewDistanceIsTypedInMetres()
        {
            string editor = Directory.GetFiles(PackageRoot.Combine("Editor"), "*.cs").Select(File.ReadAllText)
                .FirstOrDefault(t => t.Contains("[CustomEditor(typeof(CameraRangeController))"));
            Assert.That(editor, Is.Not.Null, "no inspector of CameraRangeController: View distance is drawn in terrain units");
            Assert.That(editor, Does.Contain("RendererInspectorLayout.ViewDistanceField").And.Contain("GregoryTerrainRendererEditor.DrawMetresField("));
            var f = RendererInspectorLayout.ViewDistanceField;
            Assert.That(f.label, Is.EqualTo("Range side (m)"));
            Match range = Regex.Match(Source("Runtime", "CameraRangeController.cs"), @"Range\(([-0-9.]+)f?,\s*([-0-9.]+)f?\)\]\s*float\s+" + f.field + @"\b");
            Assert.That(range.Success, "the stored field and its [Range]");
            Assert.That((f.min, f.max), Is.EqualTo((float.Parse(range.Groups[1].Value, CultureInfo.InvariantCulture), float.Parse(range.Groups[2].Value, CultureInfo.InvariantCulture))));
            Assert.That(RendererInspectorLayout.ToMetres(TerrainLength.Width, 0.5, 3000, 20000), Is.EqualTo(10000.0));
            Assert.That(RendererInspectorLayout.FromMetres(TerrainLength.Width, 250, 3000, 1000), Is.EqualTo(0.25));
            Assert.That(RendererInspectorLayout.ClampedFromMetres(TerrainLength.Width, 5e6, 600, 1000, f.min, f.max), Is.EqualTo(1f), "wider than the terrain: all of it");
            Assert.That(RendererInspectorLayout.LengthProblem(f.label, -5), Does.Contain("Range side (m)").And.Contain("-5"));
        }

        /// <summary>
        /// One meaning per label: "Height scale" is the renderer's metres per height unit only; the
        /// Patch Grid window's heights and errors say their own units, and its errors (heights) are
        /// made metres with the metres per height unit, not with the terrain's width.
        /// </summary>
        [Test]
        public void HeightScaleHasOneMeaning()
        {
            foreach (string path in Directory.GetFiles(PackageRoot.Combine("Editor"), "*.cs", SearchOption.AllDirectories))
                Assert.That(Regex.IsMatch(File.ReadAllText(path), @"GUIContent\(""Height scale", RegexOptions.IgnoreCase), Is.False,
                    $"{Path.GetFileName(path)} labels something else \"Height scale\"");
            string window = Source("Editor", "PatchGridWindow.cs");
            // The old name stays only as the setting's former name (FormerlySerializedAs), so windows keep it.
            Assert.That(window.Replace("FormerlySerializedAs(\"widthMetres\")", ""), Does.Not.Contain("widthMetres"), "fit errors are heights: metres per height unit, not the terrain's width");
            Assert.That(Regex.Matches(window, @"Error \* _unitMetres").Count, Is.GreaterThanOrEqualTo(3));
        }

        /// <summary>
        /// Horizon levels draw L levels of M^2 tiles, less the (M/2)^2 of each coarser level under the
        /// finer one (the hull stage's TileInsideFiner): counted here over real layouts, and the
        /// renderer's Most triangles counts them (not one range's M^2).
        /// </summary>
        [Test]
        public void LevelsReadoutCountsTheTilesDrawn()
        {
            foreach (int m in new[] { 8, 16, 32 })
                foreach (double metres in new[] { 1000.0, 20000.0, 1e6 })
                    foreach (var ground in new[] { new Double2(0.5, 0.5), new Double2(0.01, 0.97), new Double2(1, 0) })
                    {
                        int n = Math.Min(LodLevels.FinestExponent(metres, 16.0), LodTiles.MaxLevels - 1);
                        var levels = new TerrainRange[LodLevels.LevelCount(n)];
                        int count = LodLevels.Layout(ground, n, m, levels);
                        int drawn = 0;
                        for (int k = 0; k < count; k++)
                            for (int tj = 0; tj < m; tj++)
                                for (int ti = 0; ti < m; ti++)
                                {
                                    if (k > 0)
                                    {
                                        LodTiles.FinerOffsetCells(F4(levels[k]), F4(levels[k - 1]), m, out int a, out int b);
                                        if (LodTiles.TileInsideFiner(ti, tj, a, b, m)) continue;
                                    }
                                    drawn++;
                                }
                        Assert.That(LodLevels.DrawnTileCount(count, m), Is.EqualTo(drawn), $"M {m}, {metres} m, ground {ground}");
                    }
            TestContext.WriteLine($"1000 m terrain, M 16: {LodLevels.LevelCount(LodLevels.FinestExponent(1000, 16))} levels, " +
                                  $"{LodLevels.DrawnTileCount(LodLevels.LevelCount(LodLevels.FinestExponent(1000, 16)), 16)} tiles drawn (the readout counted 256)");
            StringAssert.Contains("levelCount (0)", Assert.Throws<ArgumentException>(() => LodLevels.DrawnTileCount(0, 16)).Message);

            string renderer = Source("Runtime", "GregoryTerrainRenderer.cs");
            Assert.That(Regex.IsMatch(renderer, @"EstimatedTriangleCount\s*=>\s*DrawnTileCount\s*\*"), "Most triangles counts the tiles drawn");
            Assert.That(renderer, Does.Contain("LodLevels.DrawnTileCount(levels, tessellation.tiles)"));
            // Triangles in view counts every level (Core's InLevels), and the inspector no longer says it is not estimated.
            Assert.That(Source("Runtime", "GregoryTerrainSurface.cs"), Does.Contain("TerrainTriangleEstimate.InLevels(").And.Not.Contain("HorizonLevels) return null"));
            Assert.That(Source("Editor", "GregoryTerrainRendererEditor.cs"), Does.Not.Contain("not estimated"));
        }

        static Float4 F4(TerrainRange r) => new Float4((float)r.c, (float)r.d, (float)r.g, (float)r.h);

        /// <summary>
        /// The per-camera work shows in the Profiler: static readonly markers (made once), their
        /// Auto() scopes (a struct: nothing allocated per frame) around the draw, its preparation and
        /// the vertex cache pass. Unity 2022.3's ProfilerMarker is in the API stubs.
        /// </summary>
        [Test]
        public void PerFrameWorkHasProfilerMarkers()
        {
            string all = RendererSources();
            var declared = Regex.Matches(all, @"static readonly ProfilerMarker (s_\w+) = new ProfilerMarker\(""(GregoryTerrainRenderer\.\w+)""\);").Cast<Match>().ToList();
            Assert.That(declared.Select(m => m.Groups[2].Value), Is.EquivalentTo(new[] { "GregoryTerrainRenderer.Draw", "GregoryTerrainRenderer.Prepare", "GregoryTerrainRenderer.VertexCache" }));
            Assert.That(Regex.Matches(all, @"new ProfilerMarker\(").Count, Is.EqualTo(declared.Count), "a marker made outside a static readonly field");
            Assert.That(Regex.IsMatch(all, @"using \(s_DrawMarker\.Auto\(\)\)\s*Draw\(cam\);"), "DrawFor's work inside the Draw marker");
            Assert.That(Regex.IsMatch(all, @"using \(s_PrepareMarker\.Auto\(\)\)\s*prepared = Prepare\(cam\);"));
            Assert.That(Regex.IsMatch(all, @"using \(s_VertexCacheMarker\.Auto\(\)\)\s*cacheReady = _cache\.UpdateFrame\(_r, fallback,"));
            string stub = Source("Tools~", "UnityApiCheck", "Stubs", "UnityEngine", "UnityEngine.Physics.cs");
            Assert.That(stub, Does.Contain("public struct ProfilerMarker").And.Contain("public AutoScope Auto()").And.Contain("public struct AutoScope : IDisposable"));
        }
    }
}
