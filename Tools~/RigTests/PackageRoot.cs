using System;
using System.IO;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>Finds the package root (the folder holding package.json) from the test assembly.</summary>
    static class PackageRoot
    {
        static string _path;

        public static string Path => _path ??= Find();

        public static string Combine(params string[] parts) => System.IO.Path.Combine(Path, System.IO.Path.Combine(parts));

        static string Find()
        {
            for (var d = new DirectoryInfo(AppContext.BaseDirectory); d != null; d = d.Parent)
            {
                if (File.Exists(System.IO.Path.Combine(d.FullName, "package.json")) &&
                    Directory.Exists(System.IO.Path.Combine(d.FullName, "Runtime")))
                    return d.FullName;
            }
            throw new InvalidOperationException(
                "package root not found above " + AppContext.BaseDirectory + " (no package.json with a Runtime folder)");
        }
    }
}
