using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The package's Shortcut Manager bindings (Editor/**/*.cs) must not take a key Unity 2022.3 binds
    /// by default where both can fire: a package shortcut in the Scene view's context would shadow a
    /// global or Scene-view default on the same key and modifiers (Z, X and V did: pivot position,
    /// pivot orientation, vertex snapping). The defaults are data, with their source:
    /// Tools~/RigTests/Data/unity-2022.3-default-shortcuts.tsv.
    /// </summary>
    [TestFixture]
    public class ShortcutClashTests
    {
        /// <summary>
        /// Contexts whose shortcuts can fire while a Scene view has focus: the global ones (and main-menu
        /// hotkeys), the Scene view's, and the contexts that UnityCsReference 2022.3 activates inside it
        /// (viewport tools, rectangle selection, fly mode, overlays, scene visibility, terrain tools).
        /// </summary>
        static readonly HashSet<string> SceneViewReachable = new HashSet<string>
        {
            "global", "Main Menu", "SceneView", "SceneViewViewport", "SceneViewViewport2D", "SceneViewViewport3D",
            "SceneViewViewportLockedPanTool", "SceneViewRectSelection", "CameraFlyModeContext", "OverlayShortcutContext",
            "SceneVisibilityManager.ShortcutContext", "TerrainToolShortcutContext", "ToolShortcutContext",
        };

        static readonly Regex Attribute = new Regex(
            @"\[(?:Shortcut|ClutchShortcut)\(\s*""(?<id>[^""]+)""\s*,\s*(?:typeof\((?<ctx>[\w\.]+)\)\s*,\s*)?KeyCode\.(?<key>\w+)(?:\s*,\s*(?<mods>ShortcutModifiers\.\w+(?:\s*\|\s*ShortcutModifiers\.\w+)*))?\s*\)\]");
        static readonly Regex AnyAttribute = new Regex(@"\[(?:Shortcut|ClutchShortcut)\(");

        sealed class Binding
        {
            public string Context, Key, Modifiers, Id, Source;
            public override string ToString() => $"{Id} ({Context}: {Modifiers}+{Key}; {Source})";
        }

        static string NormalizeModifiers(string mods) =>
            mods == null ? "None" : string.Join("|", mods.Split('|').Select(m => m.Trim().Replace("ShortcutModifiers.", "")).Where(m => m != "None").OrderBy(m => m, StringComparer.Ordinal).DefaultIfEmpty("None"));

        internal static List<(string Context, string Key, string Modifiers, string Id)> PackageShortcuts(out int attributeCount)
        {
            var found = new List<(string, string, string, string)>();
            attributeCount = 0;
            foreach (string file in Directory.GetFiles(PackageRoot.Combine("Editor"), "*.cs", SearchOption.AllDirectories))
            {
                string text = File.ReadAllText(file);
                attributeCount += AnyAttribute.Matches(text).Count;
                foreach (Match m in Attribute.Matches(text))
                    found.Add((m.Groups["ctx"].Success ? m.Groups["ctx"].Value : "global", m.Groups["key"].Value,
                        NormalizeModifiers(m.Groups["mods"].Success ? m.Groups["mods"].Value : null), m.Groups["id"].Value));
            }
            return found;
        }

        static List<Binding> UnityDefaults()
        {
            var rows = new List<Binding>();
            foreach (string line in File.ReadAllLines(PackageRoot.Combine("Tools~", "RigTests", "Data", "unity-2022.3-default-shortcuts.tsv")))
            {
                if (line.Length == 0 || line.StartsWith("#", StringComparison.Ordinal)) continue;
                string[] f = line.Split('\t');
                Assert.That(f.Length, Is.EqualTo(5), "5 tab-separated fields: " + line);
                rows.Add(new Binding { Context = f[0], Key = f[1], Modifiers = NormalizeModifiers(f[2]), Id = f[3], Source = f[4] });
            }
            return rows;
        }

        [Test]
        public void EveryPackageShortcutIsParsedAndInTheSceneViewContext()
        {
            var shortcuts = PackageShortcuts(out int attributes);
            Assert.That(shortcuts.Count, Is.EqualTo(attributes), "every [Shortcut]/[ClutchShortcut] in Editor/ has the form this test reads (\"id\", typeof(Context), KeyCode.K[, ShortcutModifiers.M])");
            Assert.That(shortcuts.Count, Is.GreaterThanOrEqualTo(4), "the package's Scene-view shortcuts");
            foreach (var s in shortcuts)
            {
                Assert.That(s.Context, Is.EqualTo("SceneView"), $"{s.Id}: bound in the Scene view's context");
                Assert.That(s.Id, Does.StartWith("Gregory Terrain/"), $"{s.Id}: in the package's own category");
            }
            Assert.That(shortcuts.Select(s => s.Id).Distinct().Count(), Is.EqualTo(shortcuts.Count), "unique ids");
            Assert.That(shortcuts.Select(s => s.Key + "+" + s.Modifiers).Distinct().Count(), Is.EqualTo(shortcuts.Count), "no two package shortcuts on one key");
        }

        [Test]
        public void NoPackageShortcutTakesAUnity2022DefaultKey()
        {
            var defaults = UnityDefaults();
            Assert.That(defaults.Count(d => d.Context == "global"), Is.GreaterThan(10), "global defaults listed");
            Assert.That(defaults.Count(d => d.Context == "SceneView"), Is.GreaterThan(3), "Scene-view defaults listed");
            var clashes = new List<string>();
            foreach (var s in PackageShortcuts(out _))
            {
                bool reachable = s.Context == "global" || s.Context == "SceneView";
                foreach (Binding d in defaults)
                {
                    bool sameScope = reachable ? SceneViewReachable.Contains(d.Context) : d.Context == s.Context || d.Context == "global" || d.Context == "Main Menu";
                    if (sameScope && d.Key == s.Key && d.Modifiers == s.Modifiers)
                        clashes.Add($"{s.Id} ({s.Modifiers}+{s.Key}) clashes with Unity's {d}");
                }
                TestContext.Out.WriteLine($"{s.Id}: {s.Context} {s.Modifiers}+{s.Key}");
            }
            Assert.That(clashes, Is.Empty, string.Join("\n", clashes));
        }
    }
}
