// STUB members the Unity-side tests use to load the package's shader in the editor, in a file of their
// own so other stub edits merge cleanly. Same rules as UnityEditor.cs: from the 2022.3 Scripting
// Reference (SR:<Page>), checked against UnityCsReference 2022.3
// (Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs:263, :355;
// Editor/Mono/SerializedObject.bindings.cs: the SerializedObject(Object) constructor).
#pragma warning disable CS1591
using UnityEngine;

namespace UnityEditor
{
    public sealed partial class AssetDatabase                                                   // SR:AssetDatabase
    {
        public static string GUIDToAssetPath(string guid) => null;                           // SR:AssetDatabase.GUIDToAssetPath
        public static T LoadAssetAtPath<T>(string assetPath) where T : Object => null;      // SR:AssetDatabase.LoadAssetAtPath
    }

    public partial class SerializedObject                                                      // SR:SerializedObject
    {
        public SerializedObject(Object obj) { }                                              // SR:SerializedObject-ctor
    }
}
