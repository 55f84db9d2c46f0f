using GregoryTerrain;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>Menu items: a terrain GameObject ready to draw; the patch grid asset itself comes from CreateAssetMenu.</summary>
    internal static class GregoryTerrainMenu
    {
        public const string ShaderName = "GregoryTerrain/Terrain";

        [MenuItem("GameObject/3D Object/Gregory Terrain", false, 10)]
        static void CreateTerrain()
        {
            var go = new GameObject("Gregory Terrain");
            go.transform.localScale = new Vector3(1000f, 1000f, 1000f);   // 1 terrain unit = 1 km
            var renderer = go.AddComponent<GregoryTerrainRenderer>();
            Shader shader = Shader.Find(ShaderName);
            if (shader != null)
            {
                var material = new Material(shader);
                AssetDatabase.CreateAsset(material, AssetDatabase.GenerateUniqueAssetPath("Assets/Gregory Terrain.mat"));
                renderer.Material = material;
            }
            else Debug.LogWarning($"Shader '{ShaderName}' not found; assign a material by hand.", go);
            var grid = ScriptableObject.CreateInstance<PatchGridAsset>();
            AssetDatabase.CreateAsset(grid, AssetDatabase.GenerateUniqueAssetPath("Assets/PatchGrid.asset"));
            renderer.Grid = grid;
            Undo.RegisterCreatedObjectUndo(go, "Create Gregory Terrain");
            Selection.activeObject = go;
        }

        [MenuItem("Window/Gregory Terrain/Patch Grid")]
        static void OpenWindow() => EditorWindow.GetWindow<PatchGridWindow>("Patch Grid");
    }
}
