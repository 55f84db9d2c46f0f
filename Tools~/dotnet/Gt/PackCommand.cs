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
            double[] o = a.Flag("orbit") ? a.Doubles("orbit", 2) : null;
            float[] orbit = o == null ? null : scene.OrbitCameraPath((int)o[0], o[1]);
            scene.WriteBuffers(dir);
            if (orbit != null) BufferFiles.Write(Path.Combine(dir, CameraPathFile), orbit);
            // The tiled noise's table (GT_NOISE_TABLE), for harness --storage-data 9:DIR/noise_cells.f32.
            if (a.Flag("noise-table")) BufferFiles.Write(Path.Combine(dir, NoiseCellsFile), GradientNoiseTable.Floats);
            Console.WriteLine(FormattableString.Invariant(
                $"packed {scene.Grid.Columns}x{scene.Grid.Rows} patches, range {scene.Range.c:R},{scene.Range.d:R},{scene.Range.g:R},{scene.Range.h:R}, tiles {scene.Tessellation.tiles} -> {dir}"));
            return 0;
        }
    }
}
