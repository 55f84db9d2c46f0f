using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli lod-cache-churn (issue 38, a measurement, not shipped): along the bench's walking and
    /// flying paths (<see cref="BenchPlan.LevelPaths"/>, 60 frames a second, the bench's LodScene at
    /// 1920 x 1080, 1 px), what a clipmap-style vertex cache of the Horizon levels would evaluate
    /// again each frame. A drawn tile's key is its level, its cell on the level's own lattice (the
    /// level's corner over its cell width plus the tile index), its integer factors as drawn
    /// (<see cref="VertexCache.IntegerFactors"/> of <see cref="TerrainTriangleEstimate.LodTileFactors"/>),
    /// and its octave window: the floor of the continuous octave count (<see cref="TerrainVertex.VertexOctaveCount"/>)
    /// at its corners and centre, lowest and highest. Per frame it counts the drawn tiles whose key
    /// is new (cell entered), whose factors changed, whose octave window changed, and the vertices
    /// the cache's vertex kernel writes for them (<see cref="VertexCache.TilePoints"/>), as fractions
    /// of the drawn ones; and the tiles and vertices whose count is fractional somewhere (below the
    /// noise's octaves), which a cache that kept the fading octave's weight would have to evaluate
    /// again every frame the camera moves. Prints; asserts nothing.
    /// </summary>
    static class LodCacheChurnCommand
    {
        public static int Run(Args a)
        {
            int frames = a.Int("frames", 60);
            PatchGrid grid = DemoGridCommand.GroundViewGrid();
            Console.WriteLine($"# lod-cache-churn: {frames} frames at {BenchPlan.FramesPerSecond} fps after the first; fractions of the drawn tiles / vertices a frame (mean, max)");
            foreach (double m in new[] { 100000.0, 1000000.0 })
                foreach (var (name, eye, speed, _) in BenchPlan.LevelPaths)
                {
                    if (speed == 0) continue;
                    var scene = new LodScene { TerrainMeters = m, EyeMeters = eye, KernelFactors = true }.Build(grid);
                    var tracker = new RangeOriginTracker();
                    tracker.Update(scene.Levels[0]);
                    Dictionary<(int, long, long), TileKey> previous = null;
                    var sum = new Churn();
                    var max = new Churn();
                    int resnaps = 0, maxFactor = 0;
                    long maxSlots = 0;
                    CountLow = float.MaxValue;
                    CountHigh = float.MinValue;
                    for (int f = 0; f <= frames; f++)
                    {
                        LodScene s = f == 0 ? scene : scene.Stepped(speed * f / BenchPlan.FramesPerSecond);
                        if (f > 0 && tracker.Update(s.Levels[0])) resnaps++;
                        var keys = Keys(s, ref maxFactor);
                        long slots = 0;
                        foreach (var k in keys.Values) slots += k.slots;
                        maxSlots = Math.Max(maxSlots, slots);
                        if (previous != null)
                        {
                            Churn c = Compare(previous, keys);
                            sum.Add(c, 1.0);
                            max.Max(c);
                        }
                        previous = keys;
                    }
                    Console.WriteLine(FormattableString.Invariant(
                        $"churn {m / 1000:F0}km {name} levels {scene.LevelCount} drawn_tiles {sum.drawnTiles / frames:F0} drawn_vertices {sum.drawnVertices / frames:F0} max_int_factor {maxFactor} origin_resnaps {resnaps} compact_record_mb {maxSlots * 16 / 1e6:F1} octave_count {CountLow:F2}..{CountHigh:F2} of {scene.Inputs.MaxNoiseOctaves()}"));
                    foreach (var (what, t, v, tm, vm) in sum.Rows(max, frames))
                        Console.WriteLine(FormattableString.Invariant($"  {what,-26} tiles {t:P2} (max {tm:P2})  vertices {v:P2} (max {vm:P2})"));
                }
            return 0;
        }

        struct TileKey
        {
            public TileFactorSet factors;
            public int octaveLow, octaveHigh, vertices, slots;
            public bool fractional;
        }

        /// <summary>Per-frame counts; fractions are formed over the drawn tiles / vertices of the frame.</summary>
        sealed class Churn
        {
            public double drawnTiles, drawnVertices;
            public double[] tiles = new double[5], vertices = new double[5];
            static readonly string[] Names = { "cell entered", "+ factors changed", "+ octave window changed", "octave window alone", "count fractional (no blend)" };

            public void Add(Churn c, double w)
            {
                drawnTiles += c.drawnTiles; drawnVertices += c.drawnVertices;
                for (int i = 0; i < tiles.Length; i++) { tiles[i] += c.tiles[i] / c.drawnTiles; vertices[i] += c.vertices[i] / c.drawnVertices; }
            }

            public void Max(Churn c)
            {
                for (int i = 0; i < tiles.Length; i++)
                {
                    tiles[i] = Math.Max(tiles[i], c.tiles[i] / c.drawnTiles);
                    vertices[i] = Math.Max(vertices[i], c.vertices[i] / c.drawnVertices);
                }
            }

            public IEnumerable<(string, double, double, double, double)> Rows(Churn max, int frames)
            {
                for (int i = 0; i < tiles.Length; i++) yield return (Names[i], tiles[i] / frames, vertices[i] / frames, max.tiles[i], max.vertices[i]);
            }
        }

        static Churn Compare(Dictionary<(int, long, long), TileKey> before, Dictionary<(int, long, long), TileKey> now)
        {
            var c = new Churn();
            foreach (var kv in now)
            {
                TileKey k = kv.Value;
                c.drawnTiles++;
                c.drawnVertices += k.vertices;
                bool entered = !before.TryGetValue(kv.Key, out TileKey old);
                bool factors = entered || !old.factors.Equals(k.factors);
                bool window = !entered && (old.octaveLow != k.octaveLow || old.octaveHigh != k.octaveHigh);
                Count(c, 0, entered, k.vertices);
                Count(c, 1, factors, k.vertices);
                Count(c, 2, factors || window, k.vertices);
                Count(c, 3, window, k.vertices);
                Count(c, 4, entered || k.fractional, k.vertices);
            }
            return c;
        }

        static void Count(Churn c, int i, bool on, int vertices)
        {
            if (!on) return;
            c.tiles[i]++;
            c.vertices[i] += vertices;
        }

        /// <summary>The lowest and highest octave count a drawn tile's samples had, over the path.</summary>
        static float CountLow, CountHigh;

        static Dictionary<(int, long, long), TileKey> Keys(LodScene s, ref int maxFactor)
        {
            TerrainInputs[] layouts = TerrainTriangleEstimate.LevelInputs(s.Inputs, s.Levels, s.Origin.Value);
            Float4x4 clip = s.Camera.ObjectToClipFloat();
            var screen = new Float2(s.Width, s.Height);
            var keys = new Dictionary<(int, long, long), TileKey>();
            int m = s.Tiles;
            float octaves = s.Inputs.MaxNoiseOctaves();
            for (int l = 0; l < s.LevelCount; l++)
            {
                TerrainRange r = s.Levels[l];
                double cell = r.Width / m;
                long ci = (long)Math.Round(r.c / cell), cj = (long)Math.Round(r.d / cell);
                for (int tj = 0; tj < m; tj++)
                    for (int ti = 0; ti < m; ti++)
                    {
                        TileFactorSet f = VertexCache.IntegerFactors(TerrainTriangleEstimate.LodTileFactors(layouts, l, ti, tj, clip, screen, TerrainKeywords.Noise));
                        if (f.IsCulled) continue;
                        float low = float.MaxValue, high = float.MinValue;
                        for (int p = 0; p < 5; p++)
                        {
                            Float2 tess = p < 4 ? new Float2(p & 1, p >> 1) : new Float2(0.5f, 0.5f);
                            TerrainPoint q = RangeMapping.ToTerrainPoint(layouts[l].Params.range, layouts[l].Params.rangeOrigin, m, ti, tj, tess.x, tess.y);
                            Float3 surface = TerrainVertex.OutputSurfacePosition(layouts[l], TerrainVertex.EvaluateSurfaceAt(layouts[l], q), TerrainKeywords.Noise);
                            float count = TerrainVertex.VertexOctaveCount(layouts[l], surface, TerrainKeywords.Noise, (clip, screen));
                            low = Math.Min(low, count);
                            high = Math.Max(high, count);
                        }
                        maxFactor = Math.Max(maxFactor, LargestFactor(f));
                        CountLow = Math.Min(CountLow, low);
                        CountHigh = Math.Max(CountHigh, high);
                        keys[(l, ci + ti, cj + tj)] = new TileKey
                        {
                            factors = f,
                            octaveLow = (int)MathF.Floor(low),
                            octaveHigh = (int)MathF.Floor(high),
                            vertices = Vertices(f),
                            slots = VertexCache.SlotsPerTile(LargestFactor(f)),
                            fractional = low < octaves,
                        };
                    }
            }
            return keys;
        }

        static int LargestFactor(TileFactorSet f) =>
            (int)Math.Max(Math.Max(Math.Max(f.edge.x, f.edge.y), Math.Max(f.edge.z, f.edge.w)), Math.Max(f.inside.x, f.inside.y));

        /// <summary>The points CacheTileVertices writes for a tile (VertexCache.TilePoints, not anchored).</summary>
        static int Vertices(TileFactorSet f) =>
            ((int)f.inside.x - 1) * ((int)f.inside.y - 1) + (int)(f.edge.x + f.edge.y + f.edge.z + f.edge.w) + 4;
    }
}
