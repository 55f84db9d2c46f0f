using GregoryTerrain;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Menu items: a terrain ready to sculpt and fly over, in metres as Unity Terrain's own menu item
    /// makes one (Transform scale 1, 1000 x 1000 m, 600 m high, Core's NewTerrainAuthoring), placed as
    /// Unity places its 3D objects; the patch grid asset itself comes from CreateAssetMenu.
    /// </summary>
    internal static class GregoryTerrainMenu
    {
        const string CreateName = "Create Gregory Terrain";

        // Beside Unity's Terrain (3000), Tree (3001) and Wind Zone (3002) in the same menu group.
        [MenuItem("GameObject/3D Object/Gregory Terrain", false, 3003)]
        static void CreateTerrain(MenuCommand command) => Create(command.context as GameObject, false);

        [MenuItem("GameObject/3D Object/Gregory Terrain with Collider", false, 3004)]
        static void CreateTerrainWithCollider(MenuCommand command) => Create(command.context as GameObject, true);

        /// <summary>
        /// The assets (grid, material), then the GameObject: one undo step removes the object; the
        /// assets stay, as Unity Terrain's TerrainData does. Placed as Unity places its 3D objects
        /// (Scene view pivot; origin with Create Objects at Origin; under <paramref name="parent"/>), selected.
        /// </summary>
        static void Create(GameObject parent, bool withCollider)
        {
            PatchGrid flat = NewTerrainAuthoring.CreateGrid();
            PatchGridAsset grid = TerrainAssets.CreateGrid(flat, "Assets/PatchGrid.asset");
            var go = new GameObject("Gregory Terrain");
            var renderer = go.AddComponent<GregoryTerrainRenderer>();
            renderer.TerrainSize = new Vector2((float)NewTerrainAuthoring.SizeMetres, (float)NewTerrainAuthoring.SizeMetres);
            renderer.HeightScale = (float)NewTerrainAuthoring.HeightMetres;
            renderer.HorizonLevels = true;
            renderer.Grid = grid;
            renderer.Material = TerrainAssets.CreateMaterial(go, noise: false);
            TerrainAssets.AssignComputeShaders(renderer);
            Undo.RegisterCreatedObjectUndo(go, CreateName);
            ObjectFactory.PlaceGameObject(go, parent);
            if (withCollider) AddColliderFollowingMainCamera(renderer);
        }

        /// <summary>
        /// A GameObject of its own (the collider moves its Transform) with a Gregory Terrain Collider
        /// around the main camera (a warning if none), beside the terrain (same parent, scene or stage).
        /// </summary>
        static void AddColliderFollowingMainCamera(GregoryTerrainRenderer renderer)
        {
            var child = new GameObject("Gregory Terrain Collider");
            PlaceBeside(child, renderer.gameObject);
            var collider = child.AddComponent<GregoryTerrainCollider>();   // RequireComponent adds the MeshCollider
            collider.Terrain = renderer;
            // In Prefab Mode the main camera is in another scene, which a prefab cannot reference.
            Camera main = EditorSceneManager.IsPreviewScene(child.scene) ? null : Camera.main;
            if (main != null) collider.Target = main.transform;
            else Debug.LogWarning("No main camera to follow here (none is tagged MainCamera, or this is Prefab Mode): set the Gregory Terrain Collider's Target by hand.", child);
            Undo.RegisterCreatedObjectUndo(child, CreateName);
        }

        /// <summary>
        /// <paramref name="go"/> where ObjectFactory put <paramref name="placed"/>: a new GameObject
        /// starts in the active scene, which is not the prefab stage or the Hierarchy's target scene.
        /// </summary>
        static void PlaceBeside(GameObject go, GameObject placed)
        {
            Transform parent = placed.transform.parent;
            if (parent != null) go.transform.SetParent(parent, false);
            else if (go.scene != placed.scene) SceneManager.MoveGameObjectToScene(go, placed.scene);
        }

        [MenuItem("Window/Gregory Terrain/Patch Grid")]
        static void OpenWindow() => EditorWindow.GetWindow<PatchGridWindow>("Patch Grid");
    }
}
