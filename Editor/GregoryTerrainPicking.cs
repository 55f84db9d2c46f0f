using System;
using UnityEditor;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Scene-view clicks select a Gregory terrain as they select a mesh. Drawn procedurally, it has no
    /// Renderer Unity could pick, so a click that picked nothing else is cast against every enabled
    /// terrain (the renderer's CPU Raycast) and the nearest hit's GameObject is selected.
    /// </summary>
    [InitializeOnLoad]
    static class GregoryTerrainPicking
    {
        static GregoryTerrainPicking() => HandleUtility.pickGameObjectCustomPasses += PickTerrain;

        // position: the camera's pixel coordinates (what ScreenPointToRay takes), not GUI points.
        static GameObject PickTerrain(Camera cam, int layers, Vector2 position, GameObject[] ignore, GameObject[] filter, out int materialIndex)
        {
            materialIndex = 0;
            if (cam == null) return null;
            Ray ray = cam.ScreenPointToRay(new Vector3(position.x, position.y, 0f));
            GameObject nearest = null;
            float nearestDistance = float.PositiveInfinity;
            foreach (GregoryTerrainRenderer terrain in UnityEngine.Object.FindObjectsByType<GregoryTerrainRenderer>(FindObjectsSortMode.None))
            {
                GameObject go = terrain.gameObject;
                if (!terrain.isActiveAndEnabled || !Pickable(go, layers, ignore, filter)) continue;
                if (terrain.Raycast(ray, nearestDistance, out _, out _, out float distance) && distance < nearestDistance)
                {
                    nearest = go;
                    nearestDistance = distance;
                }
            }
            return nearest;
        }

        static bool Pickable(GameObject go, int layers, GameObject[] ignore, GameObject[] filter)
        {
            if ((layers & (1 << go.layer)) == 0) return false;
            if (ignore != null && Array.IndexOf(ignore, go) >= 0) return false;
            return filter == null || Array.IndexOf(filter, go) >= 0;
        }
    }
}
