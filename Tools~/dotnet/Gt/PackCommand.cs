using System;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli pack: writes the harness's buffer files for one scene (see RigScene for the options);
    /// with --orbit FRAMES,DEGREES also DIR/camera_path.f32, the camera moving around the terrain
    /// (RigScene.OrbitCameraPath) for harness --camera-path; with --noise-table also DIR/noise_cells.f32,
    /// the tiled noise's table (GradientNoiseTable) for harness --storage-data 9:FILE.
    /// </summary>
    static class PackCommand
    {
        public const string CameraPathFile = "camera_path.f32";
        public const string NoiseCellsFile = "noise_cells.f32";

        public static int Run(Args a)
        {
            var scene = RigScene.FromArgs(a);
            string dir = a.String("out");
            float[] orbit = a.Flag("orbit") ? Orbit(scene, a.Doubles("orbit", 2)) : null;
            scene.WriteBuffers(dir);
            if (orbit != null) BufferFiles.Write(Path.Combine(dir, CameraPathFile), orbit);
            // The tiled noise's table (GT_NOISE_TABLE), for harness --storage-data 9:DIR/noise_cells.f32.
            if (a.Flag("noise-table")) BufferFiles.Write(Path.Combine(dir, NoiseCellsFile), GradientNoiseTable.Floats);
            Console.WriteLine(FormattableString.Invariant(
                $"packed {scene.Grid.Columns}x{scene.Grid.Rows} patches, range {scene.Range.c:R},{scene.Range.d:R},{scene.Range.g:R},{scene.Range.h:R}, tiles {scene.Tessellation.tiles} -> {dir}"));
            return 0;
        }

        static float[] Orbit(RigScene scene, double[] v)
        {
            if (!(v[0] >= 1 && v[0] <= 100000) || v[0] != Math.Floor(v[0]))
                throw new ArgumentException(FormattableString.Invariant($"--orbit: FRAMES must be a whole number in [1, 100000], got {v[0]:R}"));
            if (!(Math.Abs(v[1]) <= 90))
                throw new ArgumentException(FormattableString.Invariant($"--orbit: DEGREES must be in [-90, 90], got {v[1]:R}"));
            return scene.OrbitCameraPath((int)v[0], v[1]);
        }
    }
}
