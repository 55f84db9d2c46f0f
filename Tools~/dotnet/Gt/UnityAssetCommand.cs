using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli unity-asset: writes a patch grid (Core's JSON) as the YAML of a PatchGridAsset, the
    /// ScriptableObject in Runtime/PatchGridAsset.cs, so the sample ships the real fitted grid without
    /// a Unity editor to save it. The layout is the one Unity's text serialization gives that class
    /// in its current block layout: the grid's MonoBehaviour document (class ID 114, file ID 11400000)
    /// with, in declaration order, <c>columns</c>, <c>rows</c> (int), <c>xLines</c>, <c>yLines</c>,
    /// <c>blocks</c> (references to the block sub-assets) and an empty <c>controlPoints</c> (the older
    /// single array); then one PatchGridBlock document per block of Core's PatchGridBlocks (64 patches,
    /// 20 (x, y, z) per patch in GregoryPatch slot order, patch <c>j * n + i</c>), hidden in the
    /// hierarchy like the ones the editor adds, named "Block b", file ID 11400001 + b, with
    /// <c>owner</c> and <c>points</c>. Doubles are written round-trip ("R"), so reading them back gives
    /// the same bits. Unity reads this text as it is and saves it in binary at the first edit
    /// (PatchGridAsset is [PreferBinarySerialization]).
    /// Usage: unity-asset --grid GRID.json --out FILE.asset --script-guid GUID --block-script-guid GUID [--name NAME]
    /// </summary>
    static class UnityAssetCommand
    {
        /// <summary>File ID of the grid object in its asset (a ScriptableObject's main object).</summary>
        const long GridFileId = 11400000;

        public static int Run(Args a)
        {
            string gridPath = a.String("grid"), output = a.String("out"), guid = a.String("script-guid");
            string blockGuid = a.String("block-script-guid");
            string name = a.String("name", Path.GetFileNameWithoutExtension(output));
            if (guid.Length != 32 || !IsLowerHex(guid))
                throw new ArgumentException($"--script-guid '{guid}' must be 32 lower-case hex digits (the guid in PatchGridAsset.cs.meta)");
            if (blockGuid.Length != 32 || !IsLowerHex(blockGuid) || blockGuid == guid)
                throw new ArgumentException($"--block-script-guid '{blockGuid}' must be 32 lower-case hex digits, the guid in PatchGridBlock.cs.meta (not --script-guid's)");
            if (name.Length == 0 || name.IndexOfAny(new[] { '\n', '\r', ':', '#' }) >= 0)
                throw new ArgumentException($"--name '{name}' must be non-empty without ':', '#' or line breaks");
            PatchGrid grid = PatchGridJson.ReadFile(gridPath);
            grid.Validate();
            string yaml = Write(grid, guid, blockGuid, name);
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(output)));
            File.WriteAllText(output, yaml, new UTF8Encoding(false));
            Console.WriteLine($"{grid.Columns}x{grid.Rows} patch grid -> {output} ({PatchGridBlocks.BlockCount(grid.PatchCount)} blocks, {yaml.Length} bytes, script {guid})");
            return 0;
        }

        /// <summary>The asset's YAML text (LF line ends, as Unity writes them).</summary>
        public static string Write(PatchGrid grid, string scriptGuid, string blockScriptGuid, string name)
        {
            double[][] blocks = PatchGridBlocks.FromGrid(grid);
            var s = new StringBuilder();
            s.Append("%YAML 1.1\n");
            s.Append("%TAG !u! tag:unity3d.com,2011:\n");
            Header(s, GridFileId, hideFlags: 0, scriptGuid, name);
            s.Append("  columns: ").Append(grid.Columns.ToString(CultureInfo.InvariantCulture)).Append('\n');
            s.Append("  rows: ").Append(grid.Rows.ToString(CultureInfo.InvariantCulture)).Append('\n');
            Sequence(s, "xLines", grid.XLines);
            Sequence(s, "yLines", grid.YLines);
            s.Append("  blocks:\n");
            for (int b = 0; b < blocks.Length; b++)
                s.Append("  - {fileID: ").Append(BlockFileId(b).ToString(CultureInfo.InvariantCulture)).Append("}\n");
            s.Append("  controlPoints: []\n");
            for (int b = 0; b < blocks.Length; b++)
            {
                // HideInHierarchy (1), as PatchGridBlock.Create sets it.
                Header(s, BlockFileId(b), hideFlags: 1, blockScriptGuid, "Block " + b.ToString(CultureInfo.InvariantCulture));
                s.Append("  owner: {fileID: ").Append(GridFileId.ToString(CultureInfo.InvariantCulture)).Append("}\n");
                Sequence(s, "points", blocks[b]);
            }
            return s.ToString();
        }

        /// <summary>File ID of block <paramref name="b"/>: any ID unique in the file will do; these sort after the grid's.</summary>
        public static long BlockFileId(int b) => GridFileId + 1 + b;

        static void Header(StringBuilder s, long fileId, int hideFlags, string scriptGuid, string name)
        {
            s.Append("--- !u!114 &").Append(fileId.ToString(CultureInfo.InvariantCulture)).Append('\n');
            s.Append("MonoBehaviour:\n");
            s.Append("  m_ObjectHideFlags: ").Append(hideFlags.ToString(CultureInfo.InvariantCulture)).Append('\n');
            s.Append("  m_CorrespondingSourceObject: {fileID: 0}\n");
            s.Append("  m_PrefabInstance: {fileID: 0}\n");
            s.Append("  m_PrefabAsset: {fileID: 0}\n");
            s.Append("  m_GameObject: {fileID: 0}\n");
            s.Append("  m_Enabled: 1\n");
            s.Append("  m_EditorHideFlags: 0\n");
            s.Append("  m_Script: {fileID: 11500000, guid: ").Append(scriptGuid).Append(", type: 3}\n");
            s.Append("  m_Name: ").Append(name).Append('\n');
            s.Append("  m_EditorClassIdentifier: \n");
        }

        static void Sequence(StringBuilder s, string field, double[] values)
        {
            s.Append("  ").Append(field).Append(":\n");
            foreach (double v in values)
                s.Append("  - ").Append(v.ToString("R", CultureInfo.InvariantCulture)).Append('\n');
        }

        static bool IsLowerHex(string s)
        {
            foreach (char c in s)
                if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
            return true;
        }
    }
}
