// STUB members of UnityEditor used by the editor tools' fixes for issue 36 (the sculpt shortcut's
// guard, the Scene view's notification, the heightmap texture's import check), kept apart so that
// changes elsewhere merge cleanly. Checked against UnityCsReference 2022.3: Editor/Mono/Selection.bindings.cs,
// Editor/Mono/EditorWindow.cs, Editor/Mono/HandleUtility.cs, Editor/Mono/AssetPipeline/AssetImporter.bindings.cs,
// TextureImporter.bindings.cs, TextureImporterEnums.cs, Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs.
// SR:<Page> as in UnityEditor.cs. NOT Unity's assembly: signatures only.
#pragma warning disable CS1591
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    public sealed partial class Selection
    {
        public static GameObject[] gameObjects => null;                                      // SR:Selection-gameObjects (read only)
        public static Object[] objects { get; set; }                                         // SR:Selection-objects
    }

    public sealed partial class HandleUtility
    {
        public static int nearestControl { get => 0; set { } }                               // SR:HandleUtility-nearestControl
    }

    public partial class EditorWindow
    {
        public void ShowNotification(GUIContent notification) { }                            // SR:EditorWindow.ShowNotification
    }

    public partial class AssetImporter : Object                                              // SR:AssetImporter
    {
        public static AssetImporter GetAtPath(string path) => null;                          // SR:AssetImporter.GetAtPath
        public void SaveAndReimport() { }                                                    // SR:AssetImporter.SaveAndReimport
        public string assetPath => null;                                                     // SR:AssetImporter-assetPath
    }

    public sealed partial class TextureImporter : AssetImporter                              // SR:TextureImporter
    {
        public int maxTextureSize { get; set; }                                              // SR:TextureImporter-maxTextureSize
        public TextureImporterCompression textureCompression { get; set; }                  // SR:TextureImporter-textureCompression
        public TextureImporterNPOTScale npotScale { get; set; }                              // SR:TextureImporter-npotScale
        public bool isReadable { get; set; }                                                 // SR:TextureImporter-isReadable
        public void GetSourceTextureWidthAndHeight(out int width, out int height) { width = height = 0; } // SR:TextureImporter.GetSourceTextureWidthAndHeight
        public TextureImporterPlatformSettings GetPlatformTextureSettings(string platform) => null; // SR:TextureImporter.GetPlatformTextureSettings
        public void SetPlatformTextureSettings(TextureImporterPlatformSettings platformSettings) { } // SR:TextureImporter.SetPlatformTextureSettings
        public TextureImporterPlatformSettings GetDefaultPlatformTextureSettings() => null;   // SR:TextureImporter.GetDefaultPlatformTextureSettings
    }

    // 2022.3: Editor/Mono/AssetPipeline/TextureImporterTypes.bindings.cs (a class: the settings are copied in and out).
    public sealed partial class TextureImporterPlatformSettings                              // SR:TextureImporterPlatformSettings
    {
        public string name { get; set; }                                                     // SR:TextureImporterPlatformSettings-name
        public bool overridden { get; set; }                                                 // SR:TextureImporterPlatformSettings-overridden
        public int maxTextureSize { get; set; }                                              // SR:TextureImporterPlatformSettings-maxTextureSize
        public TextureImporterFormat format { get; set; }                                    // SR:TextureImporterPlatformSettings-format
    }

    // A subset of 2022.3's members, with their values (Editor/Mono/AssetPipeline/TextureImporterEnums.cs).
    public enum TextureImporterFormat { Automatic = -1, RGBA32 = 4, R16 = 9, RHalf = 15, RGBAHalf = 17, RFloat = 18, RGBAFloat = 20 } // SR:TextureImporterFormat

    // Subsets of 2022.3's members, with their values (Editor/Mono/BuildTarget.cs, BuildTargetGroup.cs).
    public enum BuildTarget { StandaloneOSX = 2, StandaloneWindows = 5, iOS = 9, Android = 13, StandaloneWindows64 = 19, WebGL = 20, StandaloneLinux64 = 24 } // SR:BuildTarget
    public enum BuildTargetGroup { Unknown = 0, Standalone = 1, iOS = 4, Android = 7, WebGL = 13 } // SR:BuildTargetGroup

    public class BuildPipeline                                                               // SR:BuildPipeline
    {
        public static BuildTargetGroup GetBuildTargetGroup(BuildTarget platform) => default;  // SR:BuildPipeline.GetBuildTargetGroup
    }

    public partial class EditorUserBuildSettings : Object                                    // SR:EditorUserBuildSettings
    {
        private EditorUserBuildSettings() { }                                                // private in 2022.3
        public static BuildTarget activeBuildTarget => default;                              // SR:EditorUserBuildSettings-activeBuildTarget
    }

    public enum TextureImporterCompression { Uncompressed = 0, Compressed = 1, CompressedHQ = 2, CompressedLQ = 3 } // SR:TextureImporterCompression
    public enum TextureImporterNPOTScale { None = 0, ToNearest = 1, ToLarger = 2, ToSmaller = 3 }                // SR:TextureImporterNPOTScale

    public sealed partial class AssetDatabase
    {
        public static string GetAssetPath(Object assetObject) => null;                       // SR:AssetDatabase.GetAssetPath
    }
}

namespace UnityEditor.Build
{
    // 2022.3: Editor/Mono/BuildPipeline/NamedBuildTarget.cs. TargetName is the platform name the
    // importers' platform settings use ("Standalone", "iPhone", "Android", ...).
    public readonly struct NamedBuildTarget : System.IEquatable<NamedBuildTarget>, System.IComparable<NamedBuildTarget> // SR:Build.NamedBuildTarget
    {
        public string TargetName { get; }                                                    // SR:Build.NamedBuildTarget-TargetName
        public static NamedBuildTarget FromBuildTargetGroup(BuildTargetGroup buildTargetGroup) => default; // SR:Build.NamedBuildTarget.FromBuildTargetGroup
        public bool Equals(NamedBuildTarget other) => false;                                 // SR:Build.NamedBuildTarget.Equals
        public int CompareTo(NamedBuildTarget other) => 0;                                   // SR:Build.NamedBuildTarget.CompareTo
    }
}
