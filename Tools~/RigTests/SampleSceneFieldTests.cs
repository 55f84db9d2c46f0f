using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The sample scene must be what Unity 2022.3 writes: every object has exactly the fields Unity
    /// writes for its class, no more, no fewer (Tools~/RigTests/Data/unity-2022.3-scene-fields.txt,
    /// with its source); a MonoBehaviour has the header fields and every serialized field of its
    /// script. And it carries a listener, a sky and a sun that reads right in all three pipelines.
    /// </summary>
    [TestFixture]
    public class SampleSceneFieldTests
    {
        static readonly string ScenePath = PackageRoot.Combine("Samples~", "TerrainFlyover", "Sample.unity");

        /// <summary>Every sample's scene: (sample folder, scene file). A new sample's scene is added here.</summary>
        static readonly string[][] Scenes =
        {
            new[] { "TerrainFlyover", "Sample.unity" },
            new[] { "GroundWalk", "GroundWalk.unity" },
        };

        [Test]
        public void EverySampleSceneIsListed()
        {
            var onDisk = Directory.GetFiles(PackageRoot.Combine("Samples~"), "*.unity", SearchOption.AllDirectories)
                .Select(f => Path.GetRelativePath(PackageRoot.Combine("Samples~"), f).Replace('\\', '/')).OrderBy(f => f, StringComparer.Ordinal);
            Assert.That(onDisk, Is.EqualTo(Scenes.Select(s => s[0] + "/" + s[1]).OrderBy(f => f, StringComparer.Ordinal)));
        }
        static readonly Regex Header = new Regex(@"^--- !u!(\d+) &(-?\d+)\n", RegexOptions.Multiline);

        sealed class SceneObject { public string ClassId, Anchor, ClassName, Text; public List<string> Paths; }

        static Dictionary<string, List<string>> ExpectedFields()
        {
            var map = new Dictionary<string, List<string>>();
            List<string> current = null;
            foreach (string raw in File.ReadAllLines(PackageRoot.Combine("Tools~", "RigTests", "Data", "unity-2022.3-scene-fields.txt")))
            {
                string line = raw.Trim();
                if (line.Length == 0 || line.StartsWith("#", StringComparison.Ordinal)) continue;
                if (line.StartsWith("[", StringComparison.Ordinal)) map[line.Trim('[', ']')] = current = new List<string>();
                else current.Add(line);
            }
            return map;
        }

        /// <summary>Key paths of one object, in file order: nested keys joined by '.', list items not descended.</summary>
        internal static List<string> KeyPaths(string body)
        {
            var paths = new List<string>();
            var stack = new List<(int indent, string key)>();
            foreach (string line in body.Replace("\r\n", "\n").Split('\n'))
            {
                if (line.Trim().Length == 0) continue;
                int indent = line.Length - line.TrimStart(' ').Length;
                string t = line.Trim();
                while (stack.Count > 0 && stack[^1].indent >= indent) stack.RemoveAt(stack.Count - 1);
                if (t.StartsWith("- ", StringComparison.Ordinal)) { stack.Add((indent, null)); continue; }
                if (stack.Any(s => s.key == null)) continue;
                int colon = t.IndexOf(':');
                Assert.That(colon, Is.GreaterThan(0), "not a YAML key line: " + line);
                string key = t.Substring(0, colon);
                paths.Add(string.Join(".", stack.Select(s => s.key).Append(key)));
                stack.Add((indent, key));
            }
            return paths;
        }

        static List<SceneObject> ReadScene(string text)
        {
            text = text.Replace("\r\n", "\n");
            var headers = Header.Matches(text).ToList();
            var objects = new List<SceneObject>();
            for (int k = 0; k < headers.Count; k++)
            {
                int start = headers[k].Index + headers[k].Length;
                int end = k + 1 < headers.Count ? headers[k + 1].Index : text.Length;
                string block = text.Substring(start, end - start);
                int nl = block.IndexOf('\n');
                objects.Add(new SceneObject
                {
                    ClassId = headers[k].Groups[1].Value, Anchor = headers[k].Groups[2].Value,
                    ClassName = block.Substring(0, nl).TrimEnd(':'), Text = block, Paths = KeyPaths(block.Substring(nl + 1)),
                });
            }
            return objects;
        }

        /// <summary>The serialized fields of a package script, in declaration order (SampleConsistencyTests' rule).</summary>
        static List<string> ScriptFields(string guid)
        {
            string meta = PackageRoot.FilesUnityImports("*.cs.meta")
                .Single(m => File.ReadAllText(m).Contains("guid: " + guid));
            return SerializedPaths(File.ReadAllText(meta.Substring(0, meta.Length - ".meta".Length)), "");
        }

        static readonly Regex Field = new Regex(@"^\s*(?<attrs>(\[[^\]\n]*\]\s*)*)(?<mods>((public|private|protected|internal)\s+)*)(?<type>[\w\.]+(<[\w\.,\s]+>)?(\[\])?)\s+(?<name>\w+(\s*,\s*\w+)*)\s*(=(?!>)[^;]*)?;", RegexOptions.Multiline);

        /// <summary>
        /// The key paths Unity writes for the serialized fields declared in <paramref name="source"/>:
        /// a field of a package type marked [Serializable] is written as a block, its own fields
        /// nested under its name.
        /// </summary>
        static List<string> SerializedPaths(string source, string prefix)
        {
            string text = Regex.Replace(source, @"//[^\n]*", "");
            var paths = new List<string>();
            foreach (Match m in Field.Matches(text))
            {
                string type = m.Groups["type"].Value, attrs = m.Groups["attrs"].Value, mods = m.Groups["mods"].Value;
                if (type is "return" or "using" or "static" or "const" or "readonly" or "var" or "new" or "throw") continue;
                if (!(attrs.Contains("SerializeField") || mods.Contains("public")) || attrs.Contains("NonSerialized")) continue;
                foreach (string name in m.Groups["name"].Value.Split(',').Select(n => n.Trim()))
                {
                    string path = prefix + name;
                    paths.Add(path);
                    string nested = SerializableTypeBody(type);
                    if (nested != null) paths.AddRange(SerializedPaths(nested, path + "."));
                }
            }
            return paths;
        }

        /// <summary>The body of a [Serializable] struct or class of the package's Runtime, or null.</summary>
        static string SerializableTypeBody(string type)
        {
            var declaration = new Regex(@"\[Serializable\][^{;]*?\b(struct|class)\s+" + Regex.Escape(type) + @"\b[^{]*\{");
            foreach (string file in Directory.GetFiles(PackageRoot.Combine("Runtime"), "*.cs", SearchOption.AllDirectories))
            {
                string text = File.ReadAllText(file);
                Match d = declaration.Match(text);
                if (!d.Success) continue;
                int depth = 1, i = d.Index + d.Length;
                var body = new System.Text.StringBuilder();
                for (; i < text.Length && depth > 0; i++)
                {
                    if (text[i] == '{') depth++;
                    else if (text[i] == '}') depth--;
                    // Only the type's own members: nested blocks (methods, properties) are skipped.
                    if (depth == 1 && text[i] != '}') body.Append(text[i]);
                    else if (depth == 1) body.Append(';');
                }
                return body.ToString();
            }
            return null;
        }

        static List<string> Problems(string sceneText)
        {
            var expected = ExpectedFields();
            var problems = new List<string>();
            foreach (SceneObject o in ReadScene(sceneText))
            {
                if (!expected.TryGetValue(o.ClassName, out List<string> fields))
                {
                    problems.Add($"&{o.Anchor} {o.ClassName}: no 2022.3 field list for this class");
                    continue;
                }
                var want = new List<string>(fields);
                if (o.ClassName == "MonoBehaviour")
                    want.AddRange(ScriptFields(Regex.Match(o.Text, @"m_Script: \{fileID: 11500000, guid: ([0-9a-f]{32})").Groups[1].Value));
                foreach (string missing in want.Except(o.Paths)) problems.Add($"&{o.Anchor} {o.ClassName}: missing field {missing}");
                foreach (string unknown in o.Paths.Except(want)) problems.Add($"&{o.Anchor} {o.ClassName}: unknown field {unknown}");
                if (!problems.Any(p => p.StartsWith($"&{o.Anchor} ", StringComparison.Ordinal)) && !o.Paths.SequenceEqual(want))
                    problems.Add($"&{o.Anchor} {o.ClassName}: fields not in Unity's order");
            }
            return problems;
        }

        [TestCaseSource(nameof(Scenes))]
        public void EveryObjectHasExactlyTheFieldsUnity2022Writes(string sample, string scene)
        {
            var expected = ExpectedFields();
            Assert.That(expected["Camera"].Count(p => !p.Contains('.')), Is.EqualTo(42), "Camera fields listed");
            Assert.That(expected["Light"].Count(p => !p.Contains('.')), Is.EqualTo(33), "Light fields listed");
            Assert.That(expected["RenderSettings"].Count, Is.EqualTo(28), "RenderSettings fields listed");
            var problems = Problems(File.ReadAllText(PackageRoot.Combine("Samples~", sample, scene)));
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void TheCheckFindsAMissingAndAnUnknownField()
        {
            string scene = File.ReadAllText(ScenePath).Replace("\r\n", "\n");
            string broken = scene.Replace("  m_Iso: 200\n", "").Replace("  m_ShadowAngle: 0\n", "  m_ShadowAngle: 0\n  m_LightUnit: 1\n");
            Assert.That(broken, Is.Not.EqualTo(scene));
            var problems = Problems(broken);
            Assert.That(problems, Does.Contain("&100002 Camera: missing field m_Iso"));
            Assert.That(problems, Does.Contain("&300002 Light: unknown field m_LightUnit"));
            // And on the physics objects of the walk scene (fields listed from a 2022.3 project's files).
            string walk = File.ReadAllText(PackageRoot.Combine("Samples~", "GroundWalk", "GroundWalk.unity")).Replace("\r\n", "\n");
            string brokenWalk = walk.Replace("  m_CookingOptions: 30\n", "").Replace("  m_Constraints: 112\n", "  m_Constraints: 112\n  m_MaxLinearVelocity: 100\n");
            Assert.That(brokenWalk, Is.Not.EqualTo(walk));
            var walkProblems = Problems(brokenWalk);
            Assert.That(walkProblems, Does.Contain("&400002 MeshCollider: missing field m_CookingOptions"));
            Assert.That(walkProblems, Does.Contain("&100002 Rigidbody: unknown field m_MaxLinearVelocity"));
        }

        /// <summary>
        /// Both samples in metres, one convention: the terrain's Transform at scale 1, Terrain Size and
        /// Height Scale in metres, and the detail noise (its first octave) equally high in metres.
        /// </summary>
        [Test]
        public void BothSamplesAreInMetresWithTheSameNoiseHeight()
        {
            var noiseMetres = new List<double>();
            foreach (string[] s in Scenes)
            {
                var objects = ReadScene(File.ReadAllText(PackageRoot.Combine("Samples~", s[0], s[1])));
                SceneObject renderer = objects.Single(o => o.ClassName == "MonoBehaviour" && o.Text.Contains("\n  terrainSize:"));
                string go = Regex.Match(renderer.Text, @"m_GameObject: \{fileID: -?\d+\}").Value;
                SceneObject transform = objects.Single(o => o.ClassName == "Transform" && o.Text.Contains(go));
                Assert.That(transform.Text, Does.Contain("m_LocalScale: {x: 1, y: 1, z: 1}"), s[1]);
                double Number(string key) => double.Parse(Regex.Match(renderer.Text, @"\n  " + key + @": ([-\d.eE+]+)").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
                Assert.That(Regex.Match(renderer.Text, @"terrainSize: \{x: (\d+)").Groups[1].Value, Is.EqualTo(s[0] == "GroundWalk" ? "20000" : "1000"), s[1]);
                Assert.That(Number("heightScale"), Is.GreaterThanOrEqualTo(100), s[1] + ": Height Scale in metres");
                double amplitude = double.Parse(Regex.Match(renderer.Text, @"\n  noise:\n    amplitude: ([-\d.eE+]+)").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
                noiseMetres.Add(amplitude * Number("heightScale"));
            }
            TestContext.Out.WriteLine("noise amplitude: " + string.Join(", ", noiseMetres.Select(m => m.ToString("0.###") + " m")));
            Assert.That(noiseMetres[1], Is.EqualTo(noiseMetres[0]).Within(0.01), "the same noise height in metres in both samples");
        }

        [TestCaseSource(nameof(Scenes))]
        public void SceneHasAListenerASkyAndASunForEveryPipeline(string sample, string scene)
        {
            var objects = ReadScene(File.ReadAllText(PackageRoot.Combine("Samples~", sample, scene)));
            SceneObject listener = objects.Single(o => o.ClassName == "AudioListener");
            SceneObject camera = objects.Single(o => o.ClassName == "Camera");
            Assert.That(listener.Text, Does.Contain(Regex.Match(camera.Text, @"m_GameObject: \{fileID: -?\d+\}").Value), "the listener sits on the camera");
            SceneObject render = objects.Single(o => o.ClassName == "RenderSettings");
            // Unity's Default-Skybox, as Unity writes the reference (built-in resources, type 0).
            Assert.That(render.Text, Does.Contain("m_SkyboxMaterial: {fileID: 10304, guid: 0000000000000000f000000000000000, type: 0}"));
            Assert.That(render.Text, Does.Contain("m_AmbientMode: 0"), "ambient from the skybox");
            SceneObject light = objects.Single(o => o.ClassName == "Light");
            Assert.That(render.Text, Does.Contain($"m_Sun: {{fileID: {light.Anchor}}}"), "the sky's sun is the light");
            Assert.That(camera.Text, Does.Contain("m_ClearFlags: 1"), "the camera clears to the skybox");
            // The light's GameObject runs SampleSun, which sets HDRP's lux and exposure; Built-in/URP intensity in the Light.
            string lightGo = Regex.Match(light.Text, @"m_GameObject: \{fileID: (-?\d+)\}").Groups[1].Value;
            string sunGuid = Regex.Match(File.ReadAllText(PackageRoot.Combine("Samples~", sample, "SampleSun.cs.meta")), @"guid: ([0-9a-f]{32})").Groups[1].Value;
            SceneObject sun = objects.Single(o => o.ClassName == "MonoBehaviour" && o.Text.Contains("guid: " + sunGuid));
            Assert.That(sun.Text, Does.Contain($"m_GameObject: {{fileID: {lightGo}}}"));
            double lux = double.Parse(Regex.Match(sun.Text, @"hdrpLux: ([\d.eE+]+)").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
            double ev = double.Parse(Regex.Match(sun.Text, @"hdrpExposure: ([\d.\-]+)").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
            Assert.That(lux, Is.InRange(50000, 130000), "HDRP sun in lux: clear daylight");
            // EV100 that maps the sun's illuminance to mid-grey: log2(E / 2.5) (incident-light meter constant C = 250, ISO 100).
            Assert.That(ev, Is.EqualTo(Math.Log(lux / 2.5, 2)).Within(1.0), "HDRP exposure shows that sun");
            Assert.That(objects.Any(o => o.Text.Contains("HDAdditionalLightData")), Is.False, "no HDRP component stored (a missing script in Built-in/URP)");
        }
    }
}
