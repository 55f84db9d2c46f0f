using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The demo's procedural heightmap (gt-cli demo-grid, lod-scene, jitter): a few broad hills and a
    /// ridge plus several noise octaves. Its own file so the rig tests can build gt lod-bench's terrain.
    /// </summary>
    static class DemoHeightmap
    {
        /// <summary>Heights in terrain units (the terrain is the unit square), row-major, y rows.</summary>
        public static double[] Heights(int samples)
        {
            var detail = new NoiseSettings(0.035f, 3f, 2f, 2.2f, 5);
            var h = new double[samples * samples];
            for (int j = 0; j < samples; j++)
                for (int i = 0; i < samples; i++)
                {
                    double x = i / (samples - 1.0), y = j / (samples - 1.0);
                    double hills = 0.10 * Bump(x, y, 0.30, 0.35, 0.18) + 0.14 * Bump(x, y, 0.70, 0.62, 0.15)
                                 + 0.06 * Bump(x, y, 0.55, 0.20, 0.10);
                    double ridge = 0.05 * Math.Exp(-Math.Pow((x + 0.6 * y - 0.95) / 0.06, 2));
                    double noise = OctaveNoise.Evaluate(x, y, detail, detail.octaves, out _);
                    h[j * samples + i] = hills + ridge + noise;
                }
            return h;
        }

        static double Bump(double x, double y, double cx, double cy, double r) =>
            Math.Exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (r * r));
    }
}
