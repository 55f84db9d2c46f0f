using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>The assets a new or converted terrain needs: its grid, its material and the package's compute shaders.</summary>
    internal static class TerrainAssets
    {
        public const string ShaderName = "GregoryTerrain/Terrain";

        /// <summary>
        /// The package's compute shaders by their .meta GUIDs, the same wherever it is installed. The
        /// renderer serializes the reference, so a player build carries the shader as any referenced
        /// asset. The scripts' .meta default references name the same GUIDs for Add Component.
        /// </summary>
        public const string CacheShaderGuid = "1a20dfa1a3d1ff52c7ddffa8efd311e6";
        public const string SnowSimulationGuid = "251c209b7446d79a419f2c9de7c5b002";
        public const string SnowFieldGuid = "4aecbe44fccad858b1f517bd04ed5e69";

        public static ComputeShader LoadComputeShader(string guid) =>
            AssetDatabase.LoadAssetAtPath<ComputeShader>(AssetDatabase.GUIDToAssetPath(guid));

        /// <summary>Fills the renderer's empty compute shader fields (and its snow simulator's).</summary>
        public static void AssignComputeShaders(GregoryTerrainRenderer renderer)
        {
            if (renderer.CacheShader == null) renderer.CacheShader = LoadComputeShader(CacheShaderGuid);
            SnowSimulator snow = renderer.GetComponent<SnowSimulator>();
            if (snow == null) return;
            if (snow.Simulation == null) snow.Simulation = LoadComputeShader(SnowSimulationGuid);
            if (snow.FieldShader == null) snow.FieldShader = LoadComputeShader(SnowFieldGuid);
        }

        /// <summary>
        /// A new material with every package toggle set, property and keyword alike (a material made
        /// from script gets the properties' defaults but not their keywords): height colour on, noise
        /// as asked, tiled noise and debug views off. Null, warning with <paramref name="context"/>,
        /// when the shader is missing.
        /// </summary>
        public static Material CreateMaterial(Object context, bool noise)
        {
            Shader shader = Shader.Find(ShaderName);
            if (shader == null)
            {
                Debug.LogWarning($"Shader '{ShaderName}' not found; assign a material by hand.", context);
                return null;
            }
            var material = new Material(shader);
            SetToggle(material, "_GtHeightColor", ShaderKeywords.HeightColor, true);
            SetToggle(material, "_GtNoise", ShaderKeywords.Noise, noise);
            SetToggle(material, "_GtNoiseTable", ShaderKeywords.NoiseTable, false);
            // The debug view keeps its property's default, None, which is no keyword at all.
            material.DisableKeyword(ShaderKeywords.DebugNormals);
            material.DisableKeyword(ShaderKeywords.DebugPatchId);
            material.DisableKeyword(ShaderKeywords.DebugTessFactor);
            AssetDatabase.CreateAsset(material, AssetDatabase.GenerateUniqueAssetPath("Assets/Gregory Terrain.mat"));
            return material;
        }

        static void SetToggle(Material material, string property, string keyword, bool on)
        {
            material.SetFloat(property, on ? 1f : 0f);
            if (on) material.EnableKeyword(keyword);
            else material.DisableKeyword(keyword);
        }

        /// <summary>
        /// A grid asset saved at a free path near <paramref name="path"/>, its control points in block
        /// sub-assets of the same file (else the saved grid refers to objects gone after a reload).
        /// </summary>
        public static PatchGridAsset CreateGrid(PatchGrid grid, string path)
        {
            var asset = ScriptableObject.CreateInstance<PatchGridAsset>();
            asset.SetGrid(grid, PatchGridBlocks.FromGrid(grid), out PatchGridBlock[] blocks, out _);
            AssetDatabase.CreateAsset(asset, AssetDatabase.GenerateUniqueAssetPath(path));
            foreach (PatchGridBlock b in blocks) AssetDatabase.AddObjectToAsset(b, asset);
            AssetDatabase.SaveAssetIfDirty(asset);   // AddObjectToAsset changes memory only: without this the file holds no blocks until the project is saved
            return asset;
        }
    }
}
