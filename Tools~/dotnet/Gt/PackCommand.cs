using System;

namespace GregoryTerrain.Rig
{
    /// <summary>gt-cli pack: writes the harness's buffer files for one scene (see RigScene for the options).</summary>
    static class PackCommand
    {
        public static int Run(Args a)
        {
            var scene = RigScene.FromArgs(a);
            string dir = a.String("out");
            scene.WriteBuffers(dir);
            Console.WriteLine(FormattableString.Invariant(
                $"packed {scene.Grid.Columns}x{scene.Grid.Rows} patches, range {scene.Range.c:R},{scene.Range.d:R},{scene.Range.g:R},{scene.Range.h:R}, tiles {scene.Tessellation.tiles} -> {dir}"));
            return 0;
        }
    }
}
