using System;

namespace GregoryTerrain.Tests
{
    /// <summary>Shared helpers for the patch tests: random patches and an independent Bernstein.</summary>
    static class TestPatches
    {
        public static GregoryPatch Random(int seed, double scale = 1.0)
        {
            var rng = new Random(seed);
            var p = new GregoryPatch();
            for (int k = 0; k < GregoryPatch.SlotCount; k++)
                p[k] = new Double3(scale * (2 * rng.NextDouble() - 1), scale * (2 * rng.NextDouble() - 1), scale * (2 * rng.NextDouble() - 1));
            return p;
        }

        public static Float3[] ToFloat(GregoryPatch p)
        {
            var f = new Float3[GregoryPatch.SlotCount];
            p.ToFloat(f);
            return f;
        }

        /// <summary>Cubic Bernstein polynomial from its definition C(3,i) t^i (1-t)^(3-i), independent of Core.</summary>
        public static double B3(int i, double t)
        {
            int[] binom = { 1, 3, 3, 1 };
            return binom[i] * Math.Pow(t, i) * Math.Pow(1 - t, 3 - i);
        }

        public static double MaxAbs(Double3 a) => Math.Max(Math.Abs(a.x), Math.Max(Math.Abs(a.y), Math.Abs(a.z)));
        public static double Dist(Double3 a, Double3 b) => MaxAbs(a - b);
    }
}
