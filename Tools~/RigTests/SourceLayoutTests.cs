using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>Layout the shipped C# keeps: one blank line at most between members.</summary>
    [TestFixture]
    public class SourceLayoutTests
    {
        static readonly string[] ShippedFolders = { "Runtime", "Editor", "Tests", "Samples~" };

        [Test]
        public void NoShippedCSharpFileHasTwoBlankLinesInARow()
        {
            var found = new List<string>();
            int files = 0;
            foreach (string folder in ShippedFolders)
                foreach (string path in Directory.GetFiles(PackageRoot.Combine(folder), "*.cs", SearchOption.AllDirectories))
                {
                    if (path.Contains(Path.DirectorySeparatorChar + "obj" + Path.DirectorySeparatorChar)) continue;
                    files++;
                    string[] lines = File.ReadAllLines(path);
                    for (int i = 1; i < lines.Length; i++)
                        if (lines[i].Trim().Length == 0 && lines[i - 1].Trim().Length == 0)
                            found.Add($"{Path.GetRelativePath(PackageRoot.Path, path).Replace('\\', '/')}:{i + 1}");
                }
            Assert.That(files, Is.GreaterThan(100), "shipped C# files found");
            Assert.That(found, Is.Empty, "a second blank line in a row (file:line)");
        }
    }
}
