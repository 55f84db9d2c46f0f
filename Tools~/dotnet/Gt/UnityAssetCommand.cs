using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli unity-asset: writes a patch grid (Core's JSON) as the YAML of a PatchGridAsset, the
    /// ScriptableObject in Runtime/PatchGridAsset.cs, so the sample ships the real fitted grid without
    /// a Unity editor to save it. The layout is the one Unity's text serialization gives that class:
    /// one MonoBehaviour document (class ID 114, file ID 11400000) whose fields, in declaration order,
    /// are <c>columns</c>, <c>rows</c> (int), <c>xLines</c>, <c>yLines</c>, <c>blocks</c> (empty),
    /// <c>controlPoints</c> (double[] as YAML sequences: the single-array layout PatchGridAsset loads
    /// and moves into blocks at the first edit; controlPoints holds 20 (x, y, z) per patch, GregoryPatch slot
    /// order, patch <c>j * n + i</c>). Doubles are written round-trip ("R"), so reading them back
    /// gives the same bits.
    /// Usage: unity-asset --grid GRID.json --out FILE.asset --script-guid GUID [--name NAME]
    /// </summary>
    static class UnityAssetCommand
    {
        /// <summary>Doubles per patch in controlPoints (PatchGridAsset.DoublesPerPatch).</summary>
        const int DoublesPerPatch = 3 * GregoryPatch.SlotCount;

        public static int Run(Args a)
        {
            string gridPath = a.String("grid"), output = a.String("out"), guid = a.String("script-guid");
            string name = a.String("name", Path.GetFileNameWithoutExtension(output));
            if (guid.Length != 32 || !IsLowerHex(guid))
                throw new ArgumentException($"--script-guid '{guid}' must be 32 lower-case hex digits (the guid in PatchGridAsset.cs.meta)");
            if (name.Length == 0 || name.IndexOfAny(new[] { '\n', '\r', ':', '#' }) >= 0)
                throw new ArgumentException($"--name '{name}' must be non-empty without ':', '#' or line breaks");
            PatchGrid grid = PatchGridJson.ReadFile(gridPath);
            grid.Validate();
            string yaml = Write(grid, guid, name);
            Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(output)));
            File.WriteAllText(output, yaml, new UTF8Encoding(false));
            Console.WriteLine($"{grid.Columns}x{grid.Rows} patch grid -> {output} ({yaml.Length} bytes, script {guid})");
            return 0;
        }

        /// <summary>The asset's YAML text (LF line ends, as Unity writes them).</summary>
        public static string Write(PatchGrid grid, string scriptGuid, string name)
        {
            var s = new StringBuilder();
            s.Append("%YAML 1.1\n");
            s.Append("%TAG !u! tag:unity3d.com,2011:\n");
            s.Append("--- !u!114 &11400000\n");
            s.Append("MonoBehaviour:\n");
            s.Append("  m_ObjectHideFlags: 0\n");
            s.Append("  m_CorrespondingSourceObject: {fileID: 0}\n");
            s.Append("  m_PrefabInstance: {fileID: 0}\n");
            s.Append("  m_PrefabAsset: {fileID: 0}\n");
            s.Append("  m_GameObject: {fileID: 0}\n");
            s.Append("  m_Enabled: 1\n");
            s.Append("  m_EditorHideFlags: 0\n");
            s.Append("  m_Script: {fileID: 11500000, guid: ").Append(scriptGuid).Append(", type: 3}\n");
            s.Append("  m_Name: ").Append(name).Append('\n');
            s.Append("  m_EditorClassIdentifier: \n");
            s.Append("  columns: ").Append(grid.Columns.ToString(CultureInfo.InvariantCulture)).Append('\n');
            s.Append("  rows: ").Append(grid.Rows.ToString(CultureInfo.InvariantCulture)).Append('\n');
            Sequence(s, "xLines", grid.XLines);
            Sequence(s, "yLines", grid.YLines);
            var cps = new double[grid.PatchCount * DoublesPerPatch];
            for (int p = 0; p < grid.PatchCount; p++)
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    Double3 q = grid.Patches[p][k];
                    int o = p * DoublesPerPatch + 3 * k;
                    cps[o] = q.x; cps[o + 1] = q.y; cps[o + 2] = q.z;
                }
            // No blocks yet: the grid is in the single-array layout, which PatchGridAsset still loads and
            // moves into block sub-assets at its first edit (Unity then saves it in binary).
            s.Append("  blocks: []\n");
            Sequence(s, "controlPoints", cps);
            return s.ToString();
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
