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

        /// <summary>
        /// The package's files matching <paramref name="pattern"/>, as Unity sees them: no dot-folder (.build
        /// holds the rig's work, with links back into the repository that a plain recursive walk would follow).
        /// </summary>
        public static string[] FilesUnityImports(string pattern)
        {
            var found = new System.Collections.Generic.List<string>(Directory.GetFiles(Path, pattern));
            foreach (string d in Directory.GetDirectories(Path))
                if (!System.IO.Path.GetFileName(d).StartsWith(".", StringComparison.Ordinal))
                    found.AddRange(Directory.GetFiles(d, pattern, SearchOption.AllDirectories));
            return found.ToArray();
        }

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
