using System;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The renderer's settings are Core structs (TessellationSettings, NoiseSettings, HeightColorSettings)
    /// that Core cannot annotate with [Tooltip] or [Range]: SettingFields gives each field its label,
    /// tooltip and slider, the drawers and the renderer inspector draw from it, and the renderer moves
    /// a scene's old flat fields into the structs (FlatSettingsUpgrade). Only the editor shows the
    /// sliders and only Unity runs the load: their data and the renderer's source are checked here.
    /// </summary>
    [TestFixture]
    public class SettingFieldsTests
    {
        /// <summary>What Unity serializes of a [Serializable] struct: its public instance fields, in order.</summary>
        static string[] Serialized(Type t) => t.GetFields(BindingFlags.Public | BindingFlags.Instance).Select(f => f.Name).ToArray();

        // A new renderer's values (its initialisers); each slider end is tried with the others at these.
        static object RendererDefault(string field) => field switch
        {
            "tessellation" => TessellationSettings.Default,
            "noise" => new NoiseSettings(0.02f, 16f, 2f, 2f, 6),
            _ => new HeightColorSettings(0.5f, 0.1f, 64f),
        };

        static string RendererSource() => File.ReadAllText(PackageRoot.Combine("Runtime", "GregoryTerrainRenderer.cs"));

        [Test]
        public void EveryStructFieldHasOneSliderInsideWhatValidateAccepts()
        {
            Assert.That(RendererInspectorLayout.Structs.Select(s => s.field), Is.EqualTo(new[] { "tessellation", "noise", "heightColor" }));
            foreach (var (field, fields) in RendererInspectorLayout.Structs)
            {
                object defaults = RendererDefault(field);
                Type type = defaults.GetType();
                Assert.That(RendererSource(), Does.Match(@"\[SerializeField\] " + type.Name + " " + field + " = "), "the renderer serializes the struct");
                Assert.That(fields.Select(f => f.name), Is.EqualTo(Serialized(type)), $"{type.Name}: one slider per serialized field, in Unity's order");
                Assert.That(SettingFields.Problem(defaults), Is.Null, $"{type.Name}: a new renderer's values");
                foreach (SettingField f in fields)
                {
                    Assert.That(f.label, Is.Not.Empty);
                    Assert.That(f.tooltip, Does.EndWith("."), $"{field}.{f.name}: a tooltip in plain words");
                    Assert.That(f.min, Is.LessThan(f.max));
                    FieldInfo fi = type.GetField(f.name);
                    Assert.That(f.whole || fi.FieldType == typeof(float), $"{field}.{f.name}: an int field needs an int slider");
                    foreach (float end in new[] { f.min, f.max })
                    {
                        object box = RendererDefault(field);   // a fresh boxed copy: SetValue changes the box
                        fi.SetValue(box, Convert.ChangeType(end, fi.FieldType));
                        Assert.That(SettingFields.Problem(box), Is.Null, $"{field}.{f.name} at the slider's end {end}");
                    }
                }
            }
        }

        [Test]
        public void AnInvalidValueGivesValidatesMessage()
        {
            Assert.That(SettingFields.Problem(new TessellationSettings(16, 64f, 0f, 0f)), Does.Contain("tessellation.targetPixels (0)"));
            Assert.That(SettingFields.Problem(new NoiseSettings(0.02f, 16f, 1f, 2f, 6)), Does.Contain("noise.alpha (1)"));
            Assert.That(SettingFields.Problem(new HeightColorSettings(0f, 0.1f, 64f)), Does.Contain("heightColor.gamma (0)"));
            Assert.That(SettingFields.Problem("not settings"), Is.Null);
        }

        [Test]
        public void FindNamesAStructFieldOrNothing()
        {
            Assert.That(RendererInspectorLayout.Find("tessellation.tiles")?.label, Is.EqualTo("Tiles"));
            Assert.That(RendererInspectorLayout.Find("heightColor.noiseFrequency")?.max, Is.EqualTo(4096f));
            Assert.That(RendererInspectorLayout.Find("tiles"), Is.Null);
            Assert.That(RendererInspectorLayout.Find("noise.tiles"), Is.Null);
            Assert.That(RendererInspectorLayout.Find("tessellationX.tiles"), Is.Null);
        }

        /// <summary>
        /// The old flat fields stay serialized (hidden, unset) under their old names and types, and the
        /// renderer hands each to FlatSettingsUpgrade.Move's parameter of the same name after every load:
        /// a field left out or passed to another parameter would load an old scene wrongly.
        /// </summary>
        [Test]
        public void TheRendererMovesEveryOldFieldByName()
        {
            string source = RendererSource();
            var hidden = Regex.Matches(source, @"\[SerializeField, HideInInspector, Obsolete\(\w+\)\] (int|float) (\w+) = Unset(Int|Float);")
                .Select(m => (type: m.Groups[1].Value, name: m.Groups[2].Value, unset: m.Groups[3].Value)).ToList();
            ParameterInfo[] old = typeof(FlatSettingsUpgrade).GetMethod(nameof(FlatSettingsUpgrade.Move)).GetParameters().Skip(3).ToArray();
            Assert.That(hidden.Select(h => h.name), Is.EqualTo(old.Select(p => p.Name)), "the hidden fields, in the old order, are Move's parameters");
            foreach (var (type, name, unset) in hidden)
            {
                Type t = old.Single(p => p.Name == name).ParameterType.GetElementType();
                Assert.That(type, Is.EqualTo(t == typeof(int) ? "int" : "float"), name);
                Assert.That(unset, Is.EqualTo(t == typeof(int) ? "Int" : "Float"), name);
            }
            Match call = Regex.Match(source, @"void ISerializationCallbackReceiver\.OnAfterDeserialize\(\) => Move\(ref tessellation, ref noise, ref heightColor,(?<args>[^;]*)\);");
            Assert.That(call.Success, "OnAfterDeserialize moves the old fields into the three structs");
            var args = Regex.Matches(call.Groups["args"].Value, @"(\w+): ref (\w+)").Select(m => (m.Groups[1].Value, m.Groups[2].Value)).ToList();
            Assert.That(args, Has.Count.EqualTo(old.Length), "every old field passed by name");
            Assert.That(args.Where(a => a.Item1 != a.Item2), Is.Empty, "each old field goes to the parameter of its own name");
            Assert.That(source, Does.Contain("public sealed class GregoryTerrainRenderer : MonoBehaviour, ISerializationCallbackReceiver"));
        }
    }
}
