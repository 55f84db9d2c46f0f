using System;

namespace GregoryTerrain.Tests
{
    /// <summary>Grids for the hard-case, deep-zoom and property tests (no files: built here).</summary>
    static class HardCaseGrids
    {
        /// <summary>A smooth heightmap (broad hills, heights ~0.1) of size x size samples, with a phase per seed.</summary>
        public static double[] Heightmap(int size, int seed, double amplitude = 0.1)
        {
            var rng = new Random(seed);
            double p0 = rng.NextDouble() * 6.3, p1 = rng.NextDouble() * 6.3, f0 = 1 + 3 * rng.NextDouble(), f1 = 1 + 3 * rng.NextDouble();
            var h = new double[size * size];
            for (int j = 0; j < size; j++)
                for (int i = 0; i < size; i++)
                {
                    double x = i / (size - 1.0), y = j / (size - 1.0);
                    h[j * size + i] = amplitude * (0.6 * Math.Sin(f0 * x * 3.1 + p0) * Math.Cos(f1 * y * 2.3 + p1)
                                                   + 0.4 * Math.Exp(-((x - 0.6) * (x - 0.6) + (y - 0.4) * (y - 0.4)) / 0.05));
                }
            return h;
        }

        /// <summary>A 5 x 5 G1 grid fitted to <see cref="Heightmap"/>.</summary>
        public static PatchGrid Fitted(int columns = 5, int rows = 5, int seed = 1, int samples = 33) =>
            HeightmapFitter.Fit(Heightmap(samples, seed), samples, samples, columns, rows).Grid;

        /// <summary>A flat grid on the given lines with a smooth height 0.1 sin(7x) cos(5y) through its control points.</summary>
        public static PatchGrid WithLines(double[] xl, double[] yl)
        {
            PatchGrid g = PatchGrid.CreateFlat(xl.Length - 1, yl.Length - 1, xl, yl);
            foreach (GregoryPatch p in g.Patches)
                for (int k = 0; k < 20; k++) p[k] = new Double3(p[k].x, p[k].y, 0.1 * Math.Sin(7 * p[k].x) * Math.Cos(5 * p[k].y));
            g.Validate();
            return g;
        }

        /// <summary>The float evaluation path of the shaders at a global point (no noise): patch, u v, GregoryEval float.</summary>
        public static Float3 FloatSurface(TerrainInputs grid, TerrainPoint q)
        {
            return TerrainVertex.EvaluateSurfaceAt(grid, q).position;
        }

        public static bool Finite(Float3 a) => a.IsFinite;
        public static double Dist(Float3 a, Double3 b) => TestPatches.MaxAbs(new Double3(a.x, a.y, a.z) - b);
    }
}
