using System;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli demo-grid: the sample grid of the demo and the Unity sample: 5 x 5 Gregory patches
    /// fitted to a procedural heightmap (a few broad hills and a ridge plus several noise octaves).
    /// With <c>--dem FILE</c>, the grid fitted to a square SRTM crop instead (signed 16-bit
    /// big-endian, size from its length, voids filled): heights in metres over <c>--metres-across</c>
    /// (the crop's width in metres) times <c>--exaggerate</c>, so the terrain is the unit square.
    /// </summary>
    static class DemoGridCommand
    {
        public static int Run(Args a)
        {
            string output = a.String("out");
            int columns = a.Int("columns", 5), rows = a.Int("rows", 5), samples = a.Int("samples", 257);
            string dem = a.Flag("dem") ? a.String("dem") : null;
            double[] heights;
            int width = samples, height = samples;
            if (dem != null)
            {
                byte[] bytes = File.ReadAllBytes(dem);
                string name = Path.GetFileName(dem);
                width = height = 0;
                RawHeightmap.InferSize(name, bytes.Length, RawSampleFormat.Int16BigEndian, ref width, ref height);
                heights = RawHeightmap.Decode(name, bytes, width, height, RawSampleFormat.Int16BigEndian, RawHeightmap.SrtmVoid);
                int voids = HeightmapVoids.Fill(heights, width, height);
                double across = a.Double("metres-across", 240 * 61.2), exaggerate = a.Double("exaggerate", 1.0);
                double min = double.PositiveInfinity;
                foreach (double z in heights) min = Math.Min(min, z);
                // Lowest point at 0, so the renders' height colours span the relief.
                for (int k = 0; k < heights.Length; k++) heights[k] = (heights[k] - min) * exaggerate / across;
                Console.WriteLine(FormattableString.Invariant($"{name}: {width} x {height} samples, {voids} voids filled, lowest {min} m, {across} m across, heights x {exaggerate}"));
            }
            else heights = Heightmap(samples);
            var fit = HeightmapFitter.Fit(heights, width, height, columns, rows);
            fit.Grid.Validate();
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(output)));
            File.WriteAllText(output, PatchGridJson.Write(fit.Grid));
            Console.WriteLine(FormattableString.Invariant(
                $"grid {columns}x{rows} fitted to {width}x{height} samples: max error {fit.MaxError:G3}, rms {fit.RmsError:G3}, G1 {ContinuityMeasure.MaxNormalAngleDegrees(fit.Grid):G3} deg -> {output}"));
            return 0;
        }

        /// <summary>The demo's heightmap (<see cref="DemoHeightmap.Heights"/>).</summary>
        public static double[] Heightmap(int samples) => DemoHeightmap.Heights(samples);

        /// <summary>The ground views' grid (gt-cli lod-scene, the bench's Horizon levels): the demo's terrain fitted to 129 x 129 samples, 5 x 5 patches.</summary>
        public static PatchGrid GroundViewGrid() => HeightmapFitter.Fit(Heightmap(129), 129, 129, 5, 5).Grid;
    }
}
