// STUB members of UnityEditor used by the package's editor tools for issue 23 (Scene-view shortcuts,
// the patch grid's blocks and their undo), kept apart from UnityEditor.cs so that changes made there
// for the runtime side merge cleanly. The classes are partial in Unity too (UnityCsReference 2022.3:
// Editor/Mono/Selection.cs, Editor/Mono/Undo/Undo.bindings.cs). SR:<Page> as in UnityEditor.cs.
#pragma warning disable CS1591
using System;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    [Flags]
    public enum SelectionMode { Unfiltered = 0, TopLevel = 1, Deep = 2, ExcludePrefab = 4, Editable = 8, Assets = 16, DeepAssets = 32 } // SR:SelectionMode

    public sealed partial class Selection                                                 // SR:Selection
    {
        public static T[] GetFiltered<T>(SelectionMode mode) => null;                        // SR:Selection.GetFiltered
    }

    public partial class Undo                                                             // SR:Undo
    {
        public static void RecordObjects(Object[] objectsToUndo, string name) { }            // SR:Undo.RecordObjects
    }
}

namespace UnityEditor
{
    public partial class Undo                                                            // SR:Undo
    {
        public static void DestroyObjectImmediate(Object objectToUndo) { }                   // SR:Undo.DestroyObjectImmediate
    }

    public sealed partial class AssetDatabase                                            // SR:AssetDatabase
    {
        public static bool Contains(Object obj) => false;                                    // SR:AssetDatabase.Contains
        public static void AddObjectToAsset(Object objectToAdd, Object assetObject) { }      // SR:AssetDatabase.AddObjectToAsset
    }
}

namespace UnityEditor
{
    [AttributeUsage(AttributeTargets.Class)] public class InitializeOnLoadAttribute : Attribute { } // SR:InitializeOnLoadAttribute

    public partial class Undo                                                            // SR:Undo
    {
        public delegate void UndoRedoCallback();                                             // SR:Undo.UndoRedoCallback
        public static UndoRedoCallback undoRedoPerformed;                                    // SR:Undo-undoRedoPerformed (a field in 2022.3)
    }
}
