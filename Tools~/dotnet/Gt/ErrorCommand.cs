using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli error: the largest and RMS distance between the drawn triangles and the exact surface
    /// (ErrorMeasure), for one scene (RigScene options) and its factors: read back from the GPU
    /// (--factors FILE, the GT_FACTOR_READBACK buffer) or the uniform factor (--factor F).
    /// --paper: the paper's per-patch mode (one drawn patch per Gregory patch). --with-noise: the
    /// GT_NOISE variant (the surface includes the noise). --vertex-cache: the GT_VERTEX_CACHE path,
    /// integer partitioning at the cache's integer factors: from a dump of its _TileFactors buffer
    /// (--tile-factors FILE, harness --dump-storage 7:FILE) or, without one, Core's mirror made
    /// integer as the kernel does (PatchFactors.CacheIntegers); --write-tile-factors FILE writes those
    /// Core factors in the dump's layout (to compare with a GPU dump). Prints one "error ..." line.
    /// </summary>
    static class ErrorCommand
    {
        public static int Run(Args a)
        {
            var scene = RigScene.FromArgs(a);
            bool paper = a.Flag("paper"), noise = a.Flag("with-noise");
            string factorsFile = a.String("factors", "");
            int maxCells = a.Int("max-cells", 1 << 20);
            if (a.Flag("print-factors"))
            {
                var gpu = factorsFile == "" ? null : PatchFactors.FromReadback(BufferFiles.Read(factorsFile), scene.Tessellation.tiles * scene.Tessellation.tiles);
                var core = CoreFactors(scene, a.Flag("with-noise"));
                for (int p = 0; p < core.Length; p++)
                    Console.WriteLine(FormattableString.Invariant($"tile {p} core {core[p].e0:G4} {core[p].e1:G4} {core[p].e2:G4} {core[p].e3:G4} in {core[p].i0:G4} {core[p].i1:G4}")
                        + (gpu == null ? "" : FormattableString.Invariant($" gpu {gpu[p].e0:G4} {gpu[p].e1:G4} {gpu[p].e2:G4} {gpu[p].e3:G4} in {gpu[p].i0:G4} {gpu[p].i1:G4}")));
            }
            ErrorResult result;
            if (a.Flag("vertex-cache"))
            {
                string tileFactors = a.String("tile-factors", "");
                var f = tileFactors != "" ? PatchFactors.FromTileFactors(BufferFiles.Read(tileFactors), scene.Tessellation.tiles * scene.Tessellation.tiles)
                                          : CacheFactors(scene, noise);
                string write = a.String("write-tile-factors", "");
                if (write != "") BufferFiles.Write(write, PatchFactors.ToTileFactors(CacheFactors(scene, noise)));
                result = Measure(scene, false, noise, f, maxCells, integerPartitioning: true);
            }
            else result = Measure(scene, paper, noise, factorsFile == "" ? null : BufferFiles.Read(factorsFile), maxCells);
            Console.WriteLine(result);
            return 0;
        }

        /// <summary>
        /// The vertex cache's integer factors for the scene as Core predicts them: the uniform factor,
        /// or Core's mirror of hull_const, each made integer as kernel CacheTileFactors does.
        /// </summary>
        public static PatchFactors[] CacheFactors(RigScene scene, bool noise)
        {
            var t = scene.Tessellation;
            PatchFactors[] f;
            if (t.IsUniform)
            {
                f = new PatchFactors[t.tiles * t.tiles];
                for (int p = 0; p < f.Length; p++) f[p] = PatchFactors.Uniform(t.uniformFactor);
            }
            else f = CoreFactors(scene, noise);
            for (int p = 0; p < f.Length; p++) f[p] = f[p].CacheIntegers();
            return f;
        }

        public static ErrorResult Measure(RigScene scene, bool paper, bool noise, float[] factorReadback, int maxCells, bool integerPartitioning = false)
        {
            int patches = paper ? scene.Grid.PatchCount : scene.Tessellation.tiles * scene.Tessellation.tiles;
            return Measure(scene, paper, noise, factorReadback != null ? PatchFactors.FromReadback(factorReadback, patches) : null, maxCells, integerPartitioning);
        }

        /// <summary>
        /// The error of the scene drawn with these per-patch factors (null: the uniform factor, or
        /// Core's mirror of hull_const for adaptive settings); integerPartitioning: ceil(F) equal
        /// segments (vertex cache, fallback grid), else fractional_odd.
        /// </summary>
        public static ErrorResult Measure(RigScene scene, bool paper, bool noise, PatchFactors[] factors, int maxCells, bool integerPartitioning)
        {
            var t = scene.Tessellation;
            int patches = paper ? scene.Grid.PatchCount : t.tiles * t.tiles;
            if (factors != null && factors.Length != patches)
                throw new ArgumentException($"{factors.Length} patch factors given, {patches} patches drawn");
            if (factors == null)
            {
                if (!t.IsUniform && paper) throw new ArgumentException("--paper needs --factor F (the paper's method is uniform)");
                if (!t.IsUniform) factors = CoreFactors(scene, noise);   // no readback: Core's mirror of hull_const
                else
                {
                    factors = new PatchFactors[patches];
                    for (int p = 0; p < patches; p++) factors[p] = PatchFactors.Uniform(t.uniformFactor);
                }
            }
            if (!paper) CheckSharedEdges(factors, t.tiles);
            double octaves = noise ? TerrainReference.ShaderOctaves(scene.Range, scene.Noise, t.tiles, t.maxFactor, scene.Params.noiseOctaves.y) : 0;
            var reference = new TerrainReference(scene.Grid, scene.Range, paper ? 1 : t.tiles, paper, scene.Noise, octaves);
            return ErrorMeasure.Measure(reference.ObjectPoint, factors, scene.Camera, fractionalOdd: !integerPartitioning, maxCellsPerPatch: maxCells);
        }

        /// <summary>
        /// The factors hull_const should give, from Core's mirror (TessellationPolicy, float) over the
        /// double reference surface without noise: the cross-check of the GPU readback. With
        /// <paramref name="noise"/> (the GT_NOISE variant) each edge's sagitta also holds the noise
        /// bound of the frame's octaves and the culling box its height bound.
        /// </summary>
        public static PatchFactors[] CoreFactors(RigScene scene, bool noise = false)
        {
            var t = scene.Tessellation;
            var reference = new TerrainReference(scene.Grid, scene.Range, t.tiles, false, scene.Noise, 0);
            Float4x4 m = scene.Camera.ObjectToClipFloat();
            var screen = new Float2(scene.Camera.Width, scene.Camera.Height);
            float bound = noise ? TessellationPolicy.NoiseHeightBound(scene.Noise) : 0f;
            float curvature = 0f;
            if (noise)
            {
                // The shader's octave count, in float as OctaveCount computes it (TerrainVertex.hlsl).
                float octaves = (float)TerrainReference.ShaderOctaves(scene.Range, scene.Noise, t.tiles, t.maxFactor, scene.Params.noiseOctaves.y);
                curvature = TessellationPolicy.NoiseCurvatureBound(scene.Noise, octaves);
            }
            // Tile edge lengths in terrain units (x edges run along u, y edges along v).
            float edgeX = (float)(scene.Range.Width / t.tiles), edgeY = (float)(scene.Range.Height / t.tiles);
            const int n = TessellationPolicy.EdgeSegments;
            var f = new PatchFactors[t.tiles * t.tiles];
            System.Threading.Tasks.Parallel.For(0, f.Length, p =>
            {
                Float3 P(double s, double u) { var d = reference.ObjectPoint(p, s, u); return new Float3((float)d[0], (float)d[1], (float)d[2]); }
                var corners = new[] { P(0, 0), P(1, 0), P(0, 1), P(1, 1) };
                if (TessellationPolicy.TileCulled(m, corners, bound)) { f[p] = new PatchFactors { culled = true }; return; }
                // Edge from tess (s0, t0) to (s1, t1), lower coordinate first, as hull_const walks it.
                float E(double s0, double t0, double s1, double t1, Float3 a, Float3 b, float length)
                {
                    var pts = new Float3[n + 1];
                    var k = new float[n + 1];
                    pts[0] = a; pts[n] = b;
                    float kMax = 0f;
                    for (int i = 1; i < n; i++)
                    {
                        double w = (double)i / n;
                        pts[i] = P(s0 + w * (s1 - s0), t0 + w * (t1 - t0));
                        k[i] = TessellationPolicy.PixelsPerUnit(m, pts[i], screen);
                        kMax = Math.Max(kMax, k[i]);
                    }
                    float sag = TessellationPolicy.EdgeSagittaPixels(pts, k);
                    if (noise) sag += TessellationPolicy.NoiseSagittaPixels(curvature, length, kMax);
                    return TessellationPolicy.ErrorTessFactor(sag, t.targetPixels, t.maxFactor);
                }
                var r = new PatchFactors { e0 = E(0, 0, 0, 1, corners[0], corners[2], edgeY), e1 = E(0, 0, 1, 0, corners[0], corners[1], edgeX),
                                           e2 = E(1, 0, 1, 1, corners[1], corners[3], edgeY), e3 = E(0, 1, 1, 1, corners[2], corners[3], edgeX) };
                Float3 c = P(0.5, 0.5);
                float d = TessellationPolicy.InsideErrorTessFactor(TessellationPolicy.DiagonalSagittaPixels(corners[0], corners[1], corners[2], corners[3], c,
                    TessellationPolicy.PixelsPerUnit(m, c, screen)), t.targetPixels, t.maxFactor);
                // The tile's midlines (inside factors may look inside): bumps between the edges.
                float mu = E(0, 0.5, 1, 0.5, P(0, 0.5), P(1, 0.5), edgeX), mv = E(0.5, 0, 0.5, 1, P(0.5, 0), P(0.5, 1), edgeY);
                if (Environment.GetEnvironmentVariable("GT_NO_MIDLINES") == "1") { mu = 1; mv = 1; }
                r.i0 = Math.Max(Math.Max(Math.Max(r.e1, r.e3), mu), d); r.i1 = Math.Max(Math.Max(Math.Max(r.e0, r.e2), mv), d);
                f[p] = r;
            });
            return f;
        }

        /// <summary>
        /// Crack-freedom as the GPU decided it: two neighbouring tiles that are both drawn must give
        /// their shared edge the same factor, bit for bit (float32 readback).
        /// </summary>
        public static void CheckSharedEdges(PatchFactors[] f, int tiles)
        {
            for (int tj = 0; tj < tiles; tj++)
                for (int ti = 0; ti < tiles; ti++)
                {
                    var p = f[tj * tiles + ti];
                    if (p.culled) continue;
                    if (ti + 1 < tiles && !f[tj * tiles + ti + 1].culled && p.e2 != f[tj * tiles + ti + 1].e0)
                        throw new FormatException($"crack: tile ({ti},{tj}) edge u=1 factor {p.e2:R} != tile ({ti + 1},{tj}) edge u=0 factor {f[tj * tiles + ti + 1].e0:R}");
                    if (tj + 1 < tiles && !f[(tj + 1) * tiles + ti].culled && p.e3 != f[(tj + 1) * tiles + ti].e1)
                        throw new FormatException($"crack: tile ({ti},{tj}) edge v=1 factor {p.e3:R} != tile ({ti},{tj + 1}) edge v=0 factor {f[(tj + 1) * tiles + ti].e1:R}");
                }
        }
    }
}
