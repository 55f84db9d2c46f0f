using System;
using GregoryTerrain;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Every editor change to a <see cref="PatchGridAsset"/>: one undo step each, recording only what
    /// it touches. A point move records the blocks (64 patches, 30,720 bytes of doubles each) holding
    /// the point and its shared copies; a whole-grid change (fit, flat, G1, import) the asset and the
    /// blocks whose bits change, creating or destroying block sub-assets with Undo as the count changes.
    /// </summary>
    [InitializeOnLoad]
    internal static class PatchGridAssetUndo
    {
        // Undo and redo restore grid data behind the assets' backs: every loaded grid's next read
        // compares a fingerprint of its data with the last one checked (PatchGridBlock.OnValidate too,
        // after an undo). Only a changed grid gets a new version (and is uploaded again): an undo of
        // something else costs one hash per grid.
        static PatchGridAssetUndo() => Undo.undoRedoPerformed += MarkLoadedGridsChanged;

        static void MarkLoadedGridsChanged()
        {
            foreach (PatchGridAsset grid in Resources.FindObjectsOfTypeAll<PatchGridAsset>()) grid.MarkChangedOnNextRead();
        }

        /// <summary>
        /// Moves a grid still in the older single-array layout into block sub-assets (bit for bit), as
        /// part of the current undo step. Does nothing when it already has blocks.
        /// </summary>
        public static void MoveLegacyDataToBlocks(PatchGridAsset asset, string undoName)
        {
            if (!asset.HasLegacyLayout) return;
            Undo.RecordObject(asset, undoName);
            PatchGridBlock[] created = asset.MoveLegacyDataToBlocks();
            Persist(asset, created, undoName);
            EditorUtility.SetDirty(asset);
        }

        /// <summary>
        /// Replaces the whole grid: one undo step named <paramref name="undoName"/> recording the asset
        /// (shape, lines, block list) and only the blocks whose bits change; blocks are created and
        /// destroyed with Undo.
        /// </summary>
        public static void SetGrid(PatchGridAsset asset, PatchGrid grid, string undoName)
        {
            double[][] data = PatchGridBlocks.FromGrid(grid);
            PatchGridBlock[] changed = asset.BlocksChangedBy(data);
            Undo.RecordObject(asset, undoName);
            if (changed.Length > 0) Undo.RecordObjects(changed, undoName);
            asset.SetGrid(grid, data, out PatchGridBlock[] created, out PatchGridBlock[] dropped);
            Persist(asset, created, undoName);
            foreach (PatchGridBlock b in dropped) Undo.DestroyObjectImmediate(b);
            foreach (PatchGridBlock b in changed) EditorUtility.SetDirty(b);
            EditorUtility.SetDirty(asset);
        }

        /// <summary>Moves one control point (terrain space): the undo step records only the blocks it touches.</summary>
        public static void MoveControlPoint(PatchGridAsset asset, int patch, int slot, Vector3 terrainPosition)
        {
            const string undoName = "Move control point";
            MoveLegacyDataToBlocks(asset, undoName);
            PatchGridBlock[] touched = asset.BlocksTouchedByMove(patch, slot);
            Undo.RecordObjects(touched, undoName);
            asset.SetControlPoint(patch, slot, terrainPosition);
            foreach (PatchGridBlock b in touched) EditorUtility.SetDirty(b);
        }

        /// <summary>
        /// Applies a Core edit (brush dab, region refit) to the asset, recording only the blocks it
        /// touches: within an undo group (a stroke) each dab adds its blocks.
        /// </summary>
        public static void ApplyEdit(PatchGridAsset asset, PatchEdit edit, string undoName)
        {
            if (edit.IsEmpty) return;
            MoveLegacyDataToBlocks(asset, undoName);
            PatchGridBlock[] touched = asset.BlocksOf(edit);
            Undo.RecordObjects(touched, undoName);
            asset.ApplyEdit(edit);
            foreach (PatchGridBlock b in touched) EditorUtility.SetDirty(b);
        }

        /// <summary>New blocks become hidden sub-assets of the grid's file (when it has one), undoably.</summary>
        static void Persist(PatchGridAsset asset, PatchGridBlock[] created, string undoName)
        {
            bool inFile = AssetDatabase.Contains(asset);
            foreach (PatchGridBlock b in created)
            {
                if (inFile) AssetDatabase.AddObjectToAsset(b, asset);
                Undo.RegisterCreatedObjectUndo(b, undoName);
            }
        }
    }
}
