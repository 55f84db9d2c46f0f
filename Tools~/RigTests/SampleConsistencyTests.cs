using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// What a user meets after Package Manager import -> sample import -> open scene -> Play, read from
    /// the sample's hand-written YAML (no Unity here). Each test names a break Unity would not report
    /// as an error but as a silently wrong scene: a serialized key the script no longer has (the value
    /// is dropped), a script reference that is not a MonoScript, a reference to an object of the
    /// wrong type (the field is left empty), a material property the shader does not declare, or a
    /// material keyword no toggle of the shader would set.
    /// SampleReferenceTests checks that every reference resolves at all.
    /// </summary>
    [TestFixture]
    public class SampleConsistencyTests
    {
        /// <summary>fileID of the MonoScript object inside a .cs file's import (always this value).</summary>
        const string MonoScriptFileId = "11500000";

        static readonly Regex BlockHeader = new Regex(@"^--- !u!(\d+) &(-?\d+)[^\n]*\n(\w+):\n", RegexOptions.Multiline);
        static readonly Regex MetaGuid = new Regex(@"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);
        static readonly Regex ScriptRef = new Regex(@"^  m_Script: \{fileID: (-?\d+), guid: ([0-9a-f]{32}), type: 3\}", RegexOptions.Multiline);
        static readonly Regex TopKey = new Regex(@"^  (\w+):(.*)$", RegexOptions.Multiline);
        static readonly Regex Ref = new Regex(@"^\s*\{fileID: (-?\d+)(?:, guid: ([0-9a-f]{32}), type: \d+)?\}\s*$");

        /// <summary>One YAML object: Unity class id, anchor, class name, text.</summary>
        sealed class YamlObject
        {
            public string File, ClassId, Anchor, ClassName, Text;
            public override string ToString() => $"{Path.GetFileName(File)} &{Anchor} ({ClassName})";
        }

        /// <summary>A C# script of the package: its class and serialized fields (name -> type).</summary>
        sealed class Script
        {
            public string Path, ClassName;
            public Dictionary<string, string> Fields;
        }

        Dictionary<string, string> _guidToFile;   // .meta guid -> asset path
        Dictionary<string, Script> _scripts;      // guid -> script
        List<YamlObject> _objects;

        [OneTimeSetUp]
        public void Read()
        {
            _guidToFile = new Dictionary<string, string>();
            foreach (string meta in PackageRoot.FilesUnityImports("*.meta"))
            {
                var m = MetaGuid.Match(File.ReadAllText(meta));
                if (m.Success) _guidToFile[m.Groups[1].Value] = meta.Substring(0, meta.Length - ".meta".Length);
            }
            _scripts = _guidToFile.Where(kv => kv.Value.EndsWith(".cs", StringComparison.Ordinal))
                .ToDictionary(kv => kv.Key, kv => ParseScript(kv.Value));
            _objects = new List<YamlObject>();
            string sample = PackageRoot.Combine("Samples~");
            foreach (string file in Directory.GetFiles(sample, "*", SearchOption.AllDirectories)
                         .Where(f => f.EndsWith(".unity") || f.EndsWith(".asset") || f.EndsWith(".mat")).OrderBy(f => f, StringComparer.Ordinal))
                _objects.AddRange(ParseYaml(file));
            TestContext.Out.WriteLine($"sample objects: {_objects.Count}, package scripts: {_scripts.Count}");
        }

        static IEnumerable<YamlObject> ParseYaml(string file)
        {
            string text = File.ReadAllText(file).Replace("\r\n", "\n");
            var headers = BlockHeader.Matches(text).ToList();
            for (int k = 0; k < headers.Count; k++)
            {
                int end = k + 1 < headers.Count ? headers[k + 1].Index : text.Length;
                yield return new YamlObject
                {
                    File = file, ClassId = headers[k].Groups[1].Value, Anchor = headers[k].Groups[2].Value,
                    ClassName = headers[k].Groups[3].Value, Text = text.Substring(headers[k].Index, end - headers[k].Index),
                };
            }
        }

        /// <summary>
        /// Serialized fields as Unity sees them in this package's style: instance fields marked
        /// [SerializeField] or declared public, not static/const/readonly, not properties (an
        /// expression body `=>` or accessor block is no field).
        /// </summary>
        static Script ParseScript(string path)
        {
            string text = Regex.Replace(File.ReadAllText(path), @"//[^\n]*", "");
            var fields = new Dictionary<string, string>();
            var field = new Regex(@"^\s*(?<attrs>(\[[^\]\n]*\]\s*)*)(?<mods>((public|private|protected|internal)\s+)*)(?<type>[\w\.]+(<[\w\.,\s]+>)?(\[\])?)\s+(?<name>\w+)\s*(=(?!>)[^;]*)?;",
                RegexOptions.Multiline);
            foreach (Match m in field.Matches(text))
            {
                string mods = m.Groups["mods"].Value, attrs = m.Groups["attrs"].Value, type = m.Groups["type"].Value;
                if (type is "return" or "using" or "static" or "const" or "readonly" or "var" or "new" or "throw") continue;
                bool serialized = attrs.Contains("SerializeField") || mods.Contains("public");
                if (serialized && !attrs.Contains("NonSerialized")) fields[m.Groups["name"].Value] = type;
            }
            var cls = Regex.Match(text, @"\bclass\s+(\w+)\s*:\s*(MonoBehaviour|ScriptableObject)\b");
            return new Script { Path = path, ClassName = cls.Success ? cls.Groups[1].Value : null, Fields = fields };
        }

        IEnumerable<(YamlObject obj, Script script)> ScriptedObjects()
        {
            foreach (YamlObject o in _objects.Where(o => o.ClassName == "MonoBehaviour"))
            {
                var m = ScriptRef.Match(o.Text);
                Assert.That(m.Success, Is.True, o + ": m_Script");
                Assert.That(m.Groups[1].Value, Is.EqualTo(MonoScriptFileId), o + ": m_Script must point at the MonoScript of a .cs file");
                Assert.That(_scripts.ContainsKey(m.Groups[2].Value), Is.True, o + ": m_Script guid is no .cs of the package");
                yield return (o, _scripts[m.Groups[2].Value]);
            }
        }

        static IEnumerable<(string key, string value)> SerializedKeys(YamlObject o) =>
            TopKey.Matches(o.Text).Select(m => (m.Groups[1].Value, m.Groups[2].Value.Trim())).Where(kv => !kv.Item1.StartsWith("m_"));

        [Test]
        public void EveryScriptIsAMonoBehaviourOrScriptableObjectNamedLikeItsFile()
        {
            var used = ScriptedObjects().Select(x => x.script).Distinct().ToList();
            Assert.That(used.Count, Is.GreaterThanOrEqualTo(3), "renderer, grid asset, fly-over camera");
            foreach (Script s in used)
                // Unity finds a MonoBehaviour/ScriptableObject class only in a file of the same name.
                Assert.That(s.ClassName, Is.EqualTo(Path.GetFileNameWithoutExtension(s.Path)), s.Path);
        }

        [Test]
        public void EverySerializedKeyIsASerializedFieldOfItsScript()
        {
            var problems = new List<string>();
            int keys = 0;
            foreach (var (o, script) in ScriptedObjects())
                foreach (var (key, _) in SerializedKeys(o))
                {
                    keys++;
                    if (!script.Fields.ContainsKey(key))
                        problems.Add($"{o}: '{key}' is not a serialized field of {script.ClassName} ({string.Join(", ", script.Fields.Keys)})");
                }
            TestContext.Out.WriteLine($"serialized keys checked: {keys}");
            Assert.That(keys, Is.GreaterThan(10));
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        /// <summary>
        /// A reference field must point at an object of its declared type, or Unity leaves it empty:
        /// Material -> a .mat, a script type -> a MonoBehaviour running that script.
        /// </summary>
        [Test]
        public void EveryObjectReferenceHasTheFieldsType()
        {
            int checkedRefs = 0;
            foreach (var (o, script) in ScriptedObjects())
                foreach (var (key, value) in SerializedKeys(o))
                {
                    var r = Ref.Match(value);
                    if (!r.Success || r.Groups[1].Value == "0" || !script.Fields.TryGetValue(key, out string type)) continue;
                    checkedRefs++;
                    string where = $"{o}.{key} ({type})";
                    YamlObject target;
                    if (r.Groups[2].Success)
                    {
                        Assert.That(_guidToFile.TryGetValue(r.Groups[2].Value, out string file), Is.True, where);
                        if (type == "ComputeShader")
                        {
                            // An imported compute shader is the .compute file's main object (fileID 7200000).
                            Assert.That(Path.GetExtension(file), Is.EqualTo(".compute"), where);
                            Assert.That(r.Groups[1].Value, Is.EqualTo("7200000"), where);
                            continue;
                        }
                        target = ParseYaml(file).SingleOrDefault(t => t.Anchor == r.Groups[1].Value);
                    }
                    else
                        target = _objects.SingleOrDefault(t => t.File == o.File && t.Anchor == r.Groups[1].Value);
                    Assert.That(target, Is.Not.Null, where + ": no object with that fileID");
                    if (type == "Material")
                        Assert.That(target.ClassName, Is.EqualTo("Material"), where);
                    else if (type == "Camera" || type == "Transform" || type == "Light")
                        Assert.That(target.ClassName, Is.EqualTo(type), where);
                    else
                    {
                        Assert.That(target.ClassName, Is.EqualTo("MonoBehaviour"), where);
                        string guid = ScriptRef.Match(target.Text).Groups[2].Value;
                        Assert.That(_scripts[guid].ClassName, Is.EqualTo(type), where + ": the referenced object runs another script");
                    }
                }
            TestContext.Out.WriteLine($"object references checked: {checkedRefs}");
            Assert.That(checkedRefs, Is.GreaterThanOrEqualTo(3), "grid, material, terrain");
        }

        /// <summary>The scripts each sample scene must run (besides the renderer): what the sample is about.</summary>
        static IEnumerable<TestCaseData> SceneScripts()
        {
            yield return new TestCaseData("Sample.unity", new[] { "FlyoverCamera", "SnowSimulator" });
            yield return new TestCaseData("GroundWalk.unity", new[] { "GroundWalker", "GregoryTerrainCollider", "RollingSpheres" });
        }

        [TestCaseSource(nameof(SceneScripts))]
        public void SceneHasTheTerrainACameraAndALight(string sceneFile, string[] scripts)
        {
            var scene = _objects.Where(o => Path.GetFileName(o.File) == sceneFile).ToList();
            Assert.That(scene, Is.Not.Empty, sceneFile);
            var used = ScriptedObjects().Where(x => Path.GetFileName(x.obj.File) == sceneFile).Select(x => x.script.ClassName).ToList();
            Assert.That(used, Does.Contain("GregoryTerrainRenderer"));
            foreach (string s in scripts) Assert.That(used, Does.Contain(s), sceneFile);
            Assert.That(scene.Count(o => o.ClassName == "Camera"), Is.EqualTo(1), sceneFile);
            Assert.That(Regex.IsMatch(string.Concat(scene.Where(o => o.ClassName == "GameObject").Select(o => o.Text)), @"m_TagString: MainCamera"),
                Is.True, "the camera is tagged MainCamera (Camera.main)");
            Assert.That(scene.Count(o => o.ClassName == "Light"), Is.GreaterThanOrEqualTo(1), "a main light");
            // Every component listed by a GameObject exists, and points back at it.
            foreach (YamlObject go in scene.Where(o => o.ClassName == "GameObject"))
                foreach (Match c in Regex.Matches(go.Text, @"component: \{fileID: (-?\d+)\}"))
                {
                    YamlObject comp = scene.SingleOrDefault(o => o.Anchor == c.Groups[1].Value);
                    Assert.That(comp, Is.Not.Null, go + ": component " + c.Groups[1].Value);
                    Assert.That(comp.Text, Does.Contain($"m_GameObject: {{fileID: {go.Anchor}}}"), comp + " belongs to " + go);
                }
            // A child Transform names its parent, and the parent lists it.
            foreach (YamlObject t in scene.Where(o => o.ClassName == "Transform"))
            {
                string father = Regex.Match(t.Text, @"m_Father: \{fileID: (-?\d+)\}").Groups[1].Value;
                if (father == "0") continue;
                YamlObject parent = scene.SingleOrDefault(o => o.Anchor == father && o.ClassName == "Transform");
                Assert.That(parent, Is.Not.Null, t + ": m_Father");
                Assert.That(parent.Text, Does.Contain($"- {{fileID: {t.Anchor}}}"), parent + " lists its child " + t);
            }
        }

        /// <summary>
        /// Material: the shader is GregoryTerrain.shader; every saved property is in its Properties
        /// block; every enabled keyword is one a pass declares and agrees with its toggle's value.
        /// </summary>
        [Test]
        public void MaterialPropertiesAndKeywordsExistInTheShader()
        {
            var materials = _objects.Where(o => o.ClassName == "Material").ToList();
            Assert.That(materials, Is.Not.Empty);
            foreach (YamlObject mat in materials)
            {
                var shaderRef = Regex.Match(mat.Text, @"m_Shader: \{fileID: 4800000, guid: ([0-9a-f]{32}), type: 3\}");
                Assert.That(shaderRef.Success, Is.True, mat + ": m_Shader is a shader asset (fileID 4800000)");
                Assert.That(_guidToFile.TryGetValue(shaderRef.Groups[1].Value, out string shaderFile), Is.True, mat + ": shader guid");
                Assert.That(Path.GetFileName(shaderFile), Is.EqualTo("GregoryTerrain.shader"), mat.ToString());

                // Keywords of #include_with_pragmas files are the shader's own (Unity's caching preprocessor).
                string shader = ShaderLabTests.WithIncludedPragmas(Regex.Replace(File.ReadAllText(shaderFile), @"//[^\n]*", ""));
                int open = shader.IndexOf("Properties", StringComparison.Ordinal);
                string properties = shader.Substring(open, shader.IndexOf("SubShader", open, StringComparison.Ordinal) - open);
                var declaredProps = new HashSet<string>(Regex.Matches(properties, @"^\s*(?:\[[^\]]*\]\s*)*(\w+)\s*\(""", RegexOptions.Multiline).Select(m => m.Groups[1].Value));
                var declaredKeywords = new HashSet<string>(Regex.Matches(shader, @"#pragma\s+(?:shader_feature|multi_compile)\w*\s+([^\n]+)")
                    .SelectMany(m => m.Groups[1].Value.Split(' ', StringSplitOptions.RemoveEmptyEntries)).Where(k => k != "_"));

                var saved = Regex.Matches(mat.Text, @"^    - (\w+): ", RegexOptions.Multiline).Select(m => m.Groups[1].Value).ToList();
                Assert.That(saved.Count, Is.GreaterThan(5), mat + ": saved properties");
                foreach (string p in saved)
                    Assert.That(declaredProps, Does.Contain(p), $"{mat}: saved property '{p}' is not in the shader's Properties block");

                var valid = Regex.Match(mat.Text, @"m_ValidKeywords:\n((?:  - \w+\n)*)").Groups[1].Value
                    .Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => l.Trim().TrimStart('-').Trim()).ToList();
                foreach (string k in valid)
                    Assert.That(declaredKeywords, Does.Contain(k), $"{mat}: keyword {k} is declared by no pass");
                // A [Toggle(KW)] float of 1 goes with KW enabled, 0 with it disabled.
                foreach (Match t in Regex.Matches(properties, @"\[Toggle\((\w+)\)\]\s*(\w+)"))
                {
                    var v = Regex.Match(mat.Text, @"- " + t.Groups[2].Value + @": ([\d.]+)");
                    if (!v.Success) continue;
                    Assert.That(valid.Contains(t.Groups[1].Value), Is.EqualTo(v.Groups[1].Value != "0"),
                        $"{mat}: {t.Groups[2].Value} = {v.Groups[1].Value} but keyword {t.Groups[1].Value} is {(valid.Contains(t.Groups[1].Value) ? "on" : "off")}");
                }
            }
        }
    }
}
