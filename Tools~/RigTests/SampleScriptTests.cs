using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// What the sample scripts (Samples~, compiled into the user's Assembly-CSharp) must do in a user's
    /// project that no compile here shows: no type in the global namespace (CS0101 beside a user class
    /// of the same name), input read under either Active Input Handling, no scene change in Edit Mode,
    /// and the components CreatePrimitive adds kept from engine code stripping. Each check also runs on
    /// the code it replaces, which it must reject.
    /// </summary>
    [TestFixture]
    public class SampleScriptTests
    {
        static string StripComments(string code) =>
            Regex.Replace(code, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        static Dictionary<string, string> SampleScripts() =>
            Directory.GetFiles(PackageRoot.Combine("Samples~"), "*.cs", SearchOption.AllDirectories)
                .ToDictionary(f => Path.GetRelativePath(PackageRoot.Combine("Samples~"), f).Replace('\\', '/'), File.ReadAllText);

        // ---- namespaces ----------------------------------------------------------------------------

        /// <summary>Types declared outside a namespace (brace depth 0), as "file: Name".</summary>
        internal static List<string> GlobalTypes(IDictionary<string, string> files)
        {
            var found = new List<string>();
            foreach (var f in files)
            {
                string code = StripComments(f.Value);
                foreach (Match m in Regex.Matches(code, @"\b(?:class|struct|enum|interface)\s+(\w+)"))
                {
                    string before = code.Substring(0, m.Index);
                    if (before.Count(c => c == '{') == before.Count(c => c == '}')) found.Add($"{f.Key}: {m.Groups[1].Value}");
                }
            }
            return found;
        }

        [Test]
        public void EverySampleTypeIsInTheSamplesNamespace()
        {
            var scripts = SampleScripts();
            Assert.That(GlobalTypes(scripts), Is.Empty, "sample types in the global namespace");
            foreach (var f in scripts)
            {
                string folder = f.Key.Split('/')[0];
                Assert.That(f.Value, Does.Contain($"namespace GregoryTerrain.Samples.{folder}"), f.Key);
            }
        }

        [Test]
        public void NamespaceCheckRejectsAGlobalClass()
        {
            var old = new Dictionary<string, string>
            {
                ["TerrainFlyover/FlyoverCamera.cs"] = "using UnityEngine;\n/// <summary>class in a comment</summary>\npublic sealed class FlyoverCamera : MonoBehaviour { void A() { } }",
                ["GroundWalk/GroundWalker.cs"] = "namespace GregoryTerrain.Samples.GroundWalk\n{\n    public sealed class GroundWalker : MonoBehaviour { }\n}",
            };
            Assert.That(GlobalTypes(old), Is.EqualTo(new[] { "TerrainFlyover/FlyoverCamera.cs: FlyoverCamera" }));
        }

        // ---- input ---------------------------------------------------------------------------------

        /// <summary>
        /// The lines C#'s preprocessor keeps with <paramref name="defines"/> (#if, #elif, #else, #endif;
        /// conditions of symbols, !, &amp;&amp;, || and parentheses).
        /// </summary>
        internal static string Preprocess(string code, ISet<string> defines)
        {
            var kept = new List<string>();
            var stack = new Stack<(bool parentActive, bool taken, bool active)>();
            bool active = true;
            foreach (string raw in code.Split('\n'))
            {
                string line = raw.Trim();
                Match d = Regex.Match(line, @"^#\s*(if|elif|else|endif)\b(.*)$");
                if (!d.Success) { if (active) kept.Add(raw); continue; }
                string cond = Regex.Replace(d.Groups[2].Value, @"//.*$", "").Trim();
                switch (d.Groups[1].Value)
                {
                    case "if":
                        bool v = Evaluate(cond, defines);
                        stack.Push((active, v, active && v));
                        active = active && v;
                        break;
                    case "elif":
                    {
                        var top = stack.Pop();
                        bool e = !top.taken && Evaluate(cond, defines);
                        stack.Push((top.parentActive, top.taken || e, top.parentActive && e));
                        active = top.parentActive && e;
                        break;
                    }
                    case "else":
                    {
                        var top = stack.Pop();
                        stack.Push((top.parentActive, true, top.parentActive && !top.taken));
                        active = top.parentActive && !top.taken;
                        break;
                    }
                    default:
                        active = stack.Pop().parentActive;
                        break;
                }
            }
            return string.Join("\n", kept);
        }

        static bool Evaluate(string cond, ISet<string> defines)
        {
            string e = Regex.Replace(cond, @"[A-Za-z_]\w*", m => m.Value == "true" || defines.Contains(m.Value) ? "T" : "F").Replace(" ", "");
            for (string prev = null; prev != e;)
            {
                prev = e;
                e = Regex.Replace(e, @"!T", "F"); e = Regex.Replace(e, @"!F", "T");
                e = Regex.Replace(e, @"\(([TF])\)", "$1");
                e = Regex.Replace(e, @"([TF])&&([TF])", m => m.Groups[1].Value == "T" && m.Groups[2].Value == "T" ? "T" : "F");
                e = Regex.Replace(e, @"([TF])\|\|([TF])", m => m.Groups[1].Value == "T" || m.Groups[2].Value == "T" ? "T" : "F");
            }
            if (e != "T" && e != "F") throw new System.ArgumentException($"cannot evaluate #if {cond}");
            return e == "T";
        }

        /// <summary>What the walker does with input that <paramref name="code"/>, as compiled, leaves out.</summary>
        internal static List<string> InputNotRead(string code) =>
            new[] { @"_moveX\s*=", @"_moveZ\s*=", @"_jumpRequested\s*=\s*true", @"_yaw\s*\+=", @"_pitch\s*=" }
                .Where(p => !Regex.IsMatch(StripComments(code), p)).ToList();

        [TestCase("ENABLE_INPUT_SYSTEM", "GT_INPUT_SYSTEM_PACKAGE")]
        [TestCase("ENABLE_LEGACY_INPUT_MANAGER")]
        [TestCase("ENABLE_INPUT_SYSTEM", "ENABLE_LEGACY_INPUT_MANAGER")]
        [TestCase("ENABLE_INPUT_SYSTEM", "ENABLE_LEGACY_INPUT_MANAGER", "GT_INPUT_SYSTEM_PACKAGE")]
        public void TheWalkerReadsInputUnderEveryActiveInputHandling(params string[] defines)
        {
            string walker = SampleScripts()["GroundWalk/GroundWalker.cs"];
            Assert.That(InputNotRead(Preprocess(walker, new HashSet<string>(defines))), Is.Empty,
                $"the walker's input as compiled with {string.Join(" ", defines)}");
        }

        /// <summary>
        /// ENABLE_INPUT_SYSTEM follows Active Input Handling, not the package: a project set to "Both"
        /// or "New" without com.unity.inputsystem must still compile the walker (CS0234 in a sample
        /// blocks every script of the project). The package's presence reaches the code only through
        /// the sample asmdef's versionDefines.
        /// </summary>
        [Test]
        public void TheWalkerCompilesWithoutTheInputSystemPackage()
        {
            Assert.That(UsesInputSystemNamespace(SampleScripts()["GroundWalk/GroundWalker.cs"], "ENABLE_INPUT_SYSTEM", "ENABLE_LEGACY_INPUT_MANAGER"), Is.False,
                "the walker as compiled with Active Input Handling = Both and no Input System package");
            string asmdef = File.ReadAllText(PackageRoot.Combine("Samples~", "GroundWalk", "GregoryTerrain.Samples.GroundWalk.asmdef"));
            Assert.That(Regex.IsMatch(asmdef, @"""name""\s*:\s*""com\.unity\.inputsystem""[^}]*""define""\s*:\s*""GT_INPUT_SYSTEM_PACKAGE"""), Is.True,
                "the sample asmdef defines GT_INPUT_SYSTEM_PACKAGE from the package's presence");
            // The guard this replaces: the namespace under ENABLE_INPUT_SYSTEM alone.
            Assert.That(UsesInputSystemNamespace("#if ENABLE_INPUT_SYSTEM\nusing UnityEngine.InputSystem;\n#endif", "ENABLE_INPUT_SYSTEM"), Is.True);
        }

        static bool UsesInputSystemNamespace(string code, params string[] defines) =>
            Regex.IsMatch(StripComments(Preprocess(code, new HashSet<string>(defines))), @"\bUnityEngine\.InputSystem\b|\bKeyboard\.current\b");

        [Test]
        public void InputCheckRejectsALegacyOnlyWalker()
        {
            string old = "void Update()\n{\n#if ENABLE_LEGACY_INPUT_MANAGER\n    _moveX = Input.GetAxis(\"Horizontal\");\n    _moveZ = Input.GetAxis(\"Vertical\");\n" +
                         "    if (Input.GetButtonDown(\"Jump\")) _jumpRequested = true;\n    _yaw += x;\n    _pitch = y;\n#else\n    Debug.LogWarning(\"stands still\");\n#endif\n}";
            Assert.That(InputNotRead(Preprocess(old, new HashSet<string> { "ENABLE_INPUT_SYSTEM" })).Count, Is.EqualTo(5));
            Assert.That(InputNotRead(Preprocess(old, new HashSet<string> { "ENABLE_LEGACY_INPUT_MANAGER" })), Is.Empty);
            Assert.That(Preprocess("#if !A && (B || C)\nx\n#elif A\ny\n#endif", new HashSet<string> { "A" }).Trim(), Is.EqualTo("y"));
        }

        // ---- Edit Mode leaves the scene as saved ---------------------------------------------------

        /// <summary>
        /// Writes to a light's intensity (the Light's, or HDRP's light data through reflection) in a
        /// method that does not test Application.isPlaying before them: under [ExecuteAlways] they run
        /// in Edit Mode, so opening the scene changes it.
        /// </summary>
        internal static List<string> EditModeLightWrites(string code)
        {
            code = StripComments(code);
            var found = new List<string>();
            foreach (Match w in Regex.Matches(code, @"\.\s*intensity\s*=(?!=)|SetProperty\s*\([^;]*""intensity"""))
            {
                int method = code.LastIndexOf("\n        void ", w.Index);
                string before = code.Substring(method < 0 ? 0 : method, w.Index - (method < 0 ? 0 : method));
                if (!before.Contains("Application.isPlaying"))
                {
                    int line = code.Take(w.Index).Count(c => c == '\n') + 1;
                    found.Add($"line {line}: {w.Value.Trim()}");
                }
            }
            return found;
        }

        [TestCase("GroundWalk/SampleSun.cs")]
        [TestCase("TerrainFlyover/SampleSun.cs")]
        public void SampleSunLeavesTheLightAsSavedInEditMode(string file)
        {
            string code = SampleScripts()[file];
            Assert.That(code, Does.Contain("[ExecuteAlways"), "it runs in Edit Mode");
            Assert.That(EditModeLightWrites(code), Is.Empty);
        }

        [Test]
        public void EditModeCheckRejectsAnUnguardedWrite()
        {
            string old = "        void Apply()\n        {\n            var sun = GetComponent<Light>();\n            if (!hdrp) { sun.intensity = intensity; return; }\n" +
                         "            sun.intensity = hdrpLux;\n            if (hdLight != null) SetProperty(hdLight, \"intensity\", hdrpLux);\n        }";
            Assert.That(EditModeLightWrites(old).Count, Is.EqualTo(3));
            string guarded = "        void Apply()\n        {\n            bool play = Application.isPlaying;\n            if (play) sun.intensity = lux;\n        }";
            Assert.That(EditModeLightWrites(guarded), Is.Empty);
        }

        // ---- CreatePrimitive and engine code stripping ---------------------------------------------

        /// <summary>
        /// The components GameObject.CreatePrimitive adds for each PrimitiveType, with their class IDs
        /// (the numbers a scene file lists them by).
        /// </summary>
        static readonly Dictionary<string, (string type, int id)[]> PrimitiveComponents = new Dictionary<string, (string, int)[]>
        {
            ["Sphere"] = new[] { ("MeshFilter", 33), ("MeshRenderer", 23), ("SphereCollider", 135) },
            ["Cube"] = new[] { ("MeshFilter", 33), ("MeshRenderer", 23), ("BoxCollider", 65) },
            ["Capsule"] = new[] { ("MeshFilter", 33), ("MeshRenderer", 23), ("CapsuleCollider", 136) },
            ["Cylinder"] = new[] { ("MeshFilter", 33), ("MeshRenderer", 23), ("CapsuleCollider", 136) },
            ["Plane"] = new[] { ("MeshFilter", 33), ("MeshRenderer", 23), ("MeshCollider", 64) },
            ["Quad"] = new[] { ("MeshFilter", 33), ("MeshRenderer", 23), ("MeshCollider", 64) },
        };

        /// <summary>
        /// Components a sample's CreatePrimitive calls need that neither its scripts' code nor its
        /// scenes reference: Unity's stripping keeps only the engine classes a build references
        /// (the Scripting Reference's note on CreatePrimitive), so the call fails in such a player.
        /// </summary>
        internal static List<string> StrippablePrimitiveComponents(IEnumerable<string> scripts, IEnumerable<string> scenes)
        {
            string code = string.Join("\n", scripts.Select(StripComments));
            var ids = new HashSet<int>(scenes.SelectMany(s => Regex.Matches(s, @"^--- !u!(\d+) ", RegexOptions.Multiline).Select(m => int.Parse(m.Groups[1].Value))));
            var missing = new List<string>();
            foreach (Match m in Regex.Matches(code, @"CreatePrimitive\s*\(\s*PrimitiveType\.(\w+)"))
                foreach (var (type, id) in PrimitiveComponents[m.Groups[1].Value])
                    if (!ids.Contains(id) && !Regex.IsMatch(code, $@"\b{type}\b") && !missing.Contains(type)) missing.Add(type);
            return missing;
        }

        [TestCase("GroundWalk")]
        [TestCase("TerrainFlyover")]
        public void CreatePrimitiveComponentsAreReferenced(string sample)
        {
            string dir = PackageRoot.Combine("Samples~", sample);
            var scripts = Directory.GetFiles(dir, "*.cs").Select(File.ReadAllText);
            var scenes = Directory.GetFiles(dir, "*.unity").Select(File.ReadAllText);
            Assert.That(StrippablePrimitiveComponents(scripts, scenes), Is.Empty, $"{sample}: components CreatePrimitive needs that a build could strip");
        }

        [Test]
        public void StrippingCheckRejectsAnUnreferencedSphere()
        {
            string old = "Rigidbody Create() { GameObject go = GameObject.CreatePrimitive(PrimitiveType.Sphere); // SphereCollider of radius 0.5\n return go.AddComponent<Rigidbody>(); }";
            string scene = "--- !u!54 &1\nRigidbody:\n--- !u!64 &2\nMeshCollider:\n";
            Assert.That(StrippablePrimitiveComponents(new[] { old }, new[] { scene }), Is.EqualTo(new[] { "MeshFilter", "MeshRenderer", "SphereCollider" }));
            Assert.That(StrippablePrimitiveComponents(new[] { old }, new[] { scene + "--- !u!33 &3\n--- !u!23 &4\n--- !u!135 &5\n" }), Is.Empty);
        }
    }
}
