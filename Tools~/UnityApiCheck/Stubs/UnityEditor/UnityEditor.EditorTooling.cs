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
    }

    public sealed partial class TextureImporter : AssetImporter                              // SR:TextureImporter
    {
        public int maxTextureSize { get; set; }                                              // SR:TextureImporter-maxTextureSize
        public TextureImporterCompression textureCompression { get; set; }                  // SR:TextureImporter-textureCompression
        public TextureImporterNPOTScale npotScale { get; set; }                              // SR:TextureImporter-npotScale
        public bool isReadable { get; set; }                                                 // SR:TextureImporter-isReadable
        public void GetSourceTextureWidthAndHeight(out int width, out int height) { width = height = 0; } // SR:TextureImporter.GetSourceTextureWidthAndHeight
    }

    public enum TextureImporterCompression { Uncompressed = 0, Compressed = 1, CompressedHQ = 2, CompressedLQ = 3 } // SR:TextureImporterCompression
    public enum TextureImporterNPOTScale { None = 0, ToNearest = 1, ToLarger = 2, ToSmaller = 3 }                // SR:TextureImporterNPOTScale

    public sealed partial class AssetDatabase
    {
        public static string GetAssetPath(Object assetObject) => null;                       // SR:AssetDatabase.GetAssetPath
    }
}
