using NUnit.Framework;
using System;
using System.IO;
using System.Linq;
using System.Reflection;
using static System.Text.RegularExpressions.Regex;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// FlatSettingsUpgrade.Paths, the one map of the renderer's old flat fields to their struct paths,
    /// and what reads it: the load's Move and the editor's rename of old prefab overrides
    /// (OverridePathUpgrade, run by FlatSettingsOverrideUpgrader). Only a Unity editor runs the
    /// upgrader on real prefab instances; its pure rewrite and its source's hooks are checked here.
    /// </summary>
    [TestFixture]
    public class FlatSettingsOverrideTests
    {
        static readonly (string field, Type type)[] Structs =
            { ("tessellation", typeof(TessellationSettings)), ("noise", typeof(NoiseSettings)), ("heightColor", typeof(HeightColorSettings)) };

        static string Read(params string[] path) => File.ReadAllText(PackageRoot.Combine(path));

        [Test]
        public void EveryOldFieldMapsToAStructFieldOfItsType()
        {
            ParameterInfo[] old = typeof(FlatSettingsUpgrade).GetMethod(nameof(FlatSettingsUpgrade.Move)).GetParameters().Skip(3).ToArray();
            Assert.That(FlatSettingsUpgrade.Paths.Select(p => p.old), Is.EqualTo(old.Select(p => p.Name)), "every hidden field (Move's parameters), in order");
            string renderer = Read("Runtime", "GregoryTerrainRenderer.cs");
            foreach (var (oldName, now) in FlatSettingsUpgrade.Paths)
            {
                string[] parts = now.Split('.');
                Assert.That(parts, Has.Length.EqualTo(2), now);
                var (field, type) = Structs.Single(s => s.field == parts[0]);
                Assert.That(renderer, Does.Contain($"[SerializeField] {type.Name} {field} = "), $"{now}: the renderer serializes {field}");
                FieldInfo f = type.GetField(parts[1], BindingFlags.Public | BindingFlags.Instance);
                Assert.That(f, Is.Not.Null, $"{oldName} -> {now}: {type.Name} has no field {parts[1]}");
                Type was = old.Single(p => p.Name == oldName).ParameterType.GetElementType();
                Assert.That(f.FieldType == was || (was == typeof(int) && f.FieldType == typeof(float)), $"{oldName} ({was.Name}) -> {now} ({f.FieldType.Name}): an override's value string parses as the new type");
            }
            Assert.That(FlatSettingsUpgrade.Paths.Select(p => p.now).Distinct().Count(), Is.EqualTo(FlatSettingsUpgrade.Paths.Length), "one old field per path");
        }

        /// <summary>The load moves each old field where the table says: one field set at a time, to a value no default has.</summary>
        [Test]
        public void MoveFollowsTheTable()
        {
            ParameterInfo[] ps = typeof(FlatSettingsUpgrade).GetMethod(nameof(FlatSettingsUpgrade.Move)).GetParameters();
            foreach (var (oldName, now) in FlatSettingsUpgrade.Paths)
            {
                object[] args =
                {
                    TessellationSettings.Default, new NoiseSettings(0.02f, 16f, 2f, 2f, 6), new HeightColorSettings(0.5f, 0.1f, 64f),
                };
                args = args.Concat(ps.Skip(3).Select(p => p.ParameterType.GetElementType() == typeof(int)
                    ? (object)(p.Name == oldName ? 3 : FlatSettingsUpgrade.UnsetInt)
                    : (p.Name == oldName ? 0.375f : FlatSettingsUpgrade.UnsetFloat))).ToArray();
                typeof(FlatSettingsUpgrade).GetMethod(nameof(FlatSettingsUpgrade.Move)).Invoke(null, args);
                string[] parts = now.Split('.');
                int s = Array.FindIndex(Structs, x => x.field == parts[0]);
                object moved = args[s].GetType().GetField(parts[1]).GetValue(args[s]);
                Assert.That(Convert.ToSingle(moved), Is.EqualTo(ps[3 + Array.FindIndex(FlatSettingsUpgrade.Paths, p => p.old == oldName)].ParameterType.GetElementType() == typeof(int) ? 3f : 0.375f),
                    $"{oldName} lands in {now}");
            }
        }

        sealed record Mod(object Target, string Path, string Value);

        static readonly object RendererA = new object(), RendererB = new object(), Transform = new object();

        static Mod[] Rewrite(params Mod[] mods) => OverridePathUpgrade.Rewrite(mods, m => m.Target == Transform ? null : m.Target, m => m.Path,
            (m, path) => m with { Path = path })?.ToArray();

        [Test]
        public void AnOldOverrideOnTheRendererIsRenamedAndKeepsItsValue()
        {
            Mod[] now = Rewrite(new Mod(RendererA, "tiles", "32"), new Mod(RendererA, "targetPixelError", "4"), new Mod(RendererA, "material", ""),
                new Mod(RendererA, "colorNoiseFrequency", "91"));
            Assert.That(now, Is.EqualTo(new[]
            {
                new Mod(RendererA, "tessellation.tiles", "32"), new Mod(RendererA, "tessellation.targetPixels", "4"), new Mod(RendererA, "material", ""),
                new Mod(RendererA, "heightColor.noiseFrequency", "91"),
            }));
        }

        [Test]
        public void AnotherComponentsModificationIsUntouched()
        {
            Assert.That(Rewrite(new Mod(Transform, "tiles", "32"), new Mod(RendererA, "tessellation.tiles", "8"), new Mod(RendererA, "tiles.x", "1")), Is.Null,
                "nothing to rename: another component's 'tiles', a new path, a path that only starts with an old name");
            Mod[] now = Rewrite(new Mod(Transform, "noiseBeta", "3"), new Mod(RendererA, "noiseBeta", "3"));
            Assert.That(now, Is.EqualTo(new[] { new Mod(Transform, "noiseBeta", "3"), new Mod(RendererA, "noise.beta", "3") }));
        }

        /// <summary>A stale old override beside the path now (set after the load) would move over it on every load: the newer one stays.</summary>
        [Test]
        public void AStaleOldOverrideGivesWayToTheNewPathOfTheSameRenderer()
        {
            Mod[] now = Rewrite(new Mod(RendererA, "tiles", "32"), new Mod(RendererA, "tessellation.tiles", "48"), new Mod(RendererB, "tiles", "24"));
            Assert.That(now, Is.EqualTo(new[] { new Mod(RendererA, "tessellation.tiles", "48"), new Mod(RendererB, "tessellation.tiles", "24") }));
        }

        /// <summary>Unity runs the upgrader; its source is checked for where it runs and how it edits (editor-only behaviour).</summary>
        [Test]
        public void TheUpgraderIsAnExplicitProjectPassThatLeavesNothingHalfDone()
        {
            string path = PackageRoot.Combine("Editor", "FlatSettingsOverrideUpgrader.cs");
            Assert.That(File.Exists(path), "Editor/FlatSettingsOverrideUpgrader.cs renames old prefab overrides");
            string s = File.ReadAllText(path);
            Assert.That(s, Does.Not.Contain("sceneOpened").And.Not.Contain("prefabStageOpened").And.Not.Contain("[InitializeOnLoad]"),
                "opening a scene or a prefab never modifies it (read-only files, Prefab Mode's Auto Save)");
            Assert.That(s, Does.Contain("[MenuItem(MenuPath)]").And.Contain("[MenuItem(MenuPath, true)]"), "the menu item, refused in Play Mode");
            Assert.That(s, Does.Contain("const string Title = \"Upgrade Gregory Terrain overrides\";"));
            Assert.That(s, Does.Contain("EditorUtility.DisplayCancelableProgressBar(").And.Contain("EditorUtility.ClearProgressBar()"), "progress with Cancel");
            Assert.That(s, Does.Contain("OverridePathUpgrade.Rewrite(mods, m => m.target as GregoryTerrainRenderer,"), "the renderer's modifications only");
            Assert.That(s, Does.Contain(@"p.EndsWith("".prefab"") || p.EndsWith("".unity"")"), "model files match t:Prefab; LoadPrefabContents throws on them");
            Assert.That(s, Does.Contain("PrefabStageUtility.GetCurrentPrefabStage() != null"), "an open Prefab Mode's unsaved edits are not overwritten");
            Assert.That(s, Does.Contain("scene.isDirty"), "a scene the user chose not to save is left alone");
            Assert.That(s, Does.Contain("EditorSceneManager.SaveScene(scene)) return null;").And.Contain("out bool saved"), "a file that could not be saved is reported, not counted");
            Assert.That(s, Does.Contain("catch (Exception e)"), "one file's failure does not end the pass");
        }

        [Test]
        public void TheDrawersMessageIsEverySelectedObjects()
        {
            Assert.That(SettingFields.Problem(new (string, object)[] { ("A", TessellationSettings.Default), ("B", new TessellationSettings(16, 64f, 0f, 0f)) }),
                Does.StartWith("B: ").And.Contain("tessellation.targetPixels (0)"), "the second selected object's invalid value shows, named");
            Assert.That(SettingFields.Problem(new (string, object)[] { ("A", new NoiseSettings(0.02f, 16f, 1f, 2f, 6)) }), Does.StartWith("noise.alpha"), "one selected: not named");
            Assert.That(SettingFields.Problem(new (string, object)[] { ("A", TessellationSettings.Default), ("B", TessellationSettings.Default) }), Is.Null);
            string drawer = Read("Editor", "SettingsDrawers.cs");
            Assert.That(drawer, Does.Contain("property.serializedObject.targetObjects").And.Contain("fieldInfo.GetValue(t)"), "each selected object's own value");
            Assert.That(Matches(drawer, @"SettingFields\.Problem\(").Count, Is.EqualTo(1), "one validation helper, called by GetPropertyHeight and OnGUI");
            Assert.That(drawer, Does.Not.Match(@"\n\s*(string|object|bool)\s+_\w+\s*;"), "no per-property state: Unity shares one drawer among an array's elements");
        }
    }
}
