using System.Collections.Generic;
using UnityEngine;

namespace GregoryTerrain.Tests
{
    /// <summary>Runs a fixture in the editor only (Edit and Play Mode), not in a player.</summary>
    public sealed class EditorOnlyAttribute : UnityEngine.TestTools.UnityPlatformAttribute
    {
        public EditorOnlyAttribute() : base(RuntimePlatform.WindowsEditor, RuntimePlatform.OSXEditor, RuntimePlatform.LinuxEditor) { }
    }

    /// <summary>
    /// A renderer on a 2 x 2 flat grid with the package's terrain shader, and cameras, made for one
    /// test and destroyed after it (<see cref="Dispose"/>).
    /// </summary>
    public sealed class TestTerrain : System.IDisposable
    {
        readonly List<Object> _made = new List<Object>();

        public Material Asset { get; }
        public PatchGridAsset Grid { get; }

        const string ShaderGuid = "d10911ff66aad0d4ff5ba251996825e9";   // Shaders/GregoryTerrain.shader.meta

        // From the AssetDatabase: a player's Shader.Find sees only shaders its build holds ([EditorOnly]).
        public TestTerrain()
        {
#if UNITY_EDITOR
            Shader shader = UnityEditor.AssetDatabase.LoadAssetAtPath<Shader>(UnityEditor.AssetDatabase.GUIDToAssetPath(ShaderGuid));
#else
            Shader shader = null;
#endif
            if (shader == null) throw new System.InvalidOperationException($"shader GregoryTerrain/Terrain (GUID {ShaderGuid}) not found: is the package imported?");
            Asset = Keep(new Material(shader));
            Grid = Keep(ScriptableObject.CreateInstance<PatchGridAsset>());
            Grid.SetGrid(PatchGrid.CreateFlat(2, 2));
        }

        /// <summary>An enabled renderer drawing <see cref="Grid"/> with <see cref="Asset"/>.</summary>
        public GregoryTerrainRenderer Renderer(string name)
        {
            var go = Keep(new GameObject(name));
            go.SetActive(false);
            var r = go.AddComponent<GregoryTerrainRenderer>();
            r.Grid = Grid;
            r.Material = Asset;
            go.SetActive(true);   // OnEnable with the content assigned
            return r;
        }

        public Camera Camera(string name)
        {
            var go = Keep(new GameObject(name));
            return go.AddComponent<Camera>();
        }

        T Keep<T>(T o) where T : Object { _made.Add(o); return o; }

        public void Dispose()
        {
            for (int i = _made.Count - 1; i >= 0; i--)
                if (_made[i] != null) Object.DestroyImmediate(_made[i]);
            _made.Clear();
        }
    }
}
