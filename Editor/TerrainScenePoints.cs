using System;
using GregoryTerrain;
using UnityEngine;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Where the Scene view draws a control point and a handle drag puts it back: through the
    /// renderer's <see cref="GregoryTerrainRenderer.WorldFrame"/> (Transform, Terrain Size, Height
    /// Scale, floating-origin offset), as its draw matrices, not the Transform alone. Positions are
    /// world: leave <c>Handles.matrix</c> at identity.
    /// </summary>
    internal readonly struct TerrainScenePoints
    {
        readonly TerrainWorldFrame _frame;

        TerrainScenePoints(TerrainWorldFrame frame) { _frame = frame; }

        /// <summary>The renderer's mapping now; false (nothing to draw) while its Transform cannot be inverted (a zero scale).</summary>
        public static bool TryGet(GregoryTerrainRenderer renderer, out TerrainScenePoints points)
        {
            try { points = new TerrainScenePoints(renderer.WorldFrame); return true; }
            catch (ArgumentException) { points = default; return false; }
        }

        /// <summary>A control point (terrain x, y, height z) in the world.</summary>
        public Vector3 ToWorld(Vector3 terrain)
        {
            Double3 w = _frame.TerrainToWorld(new Double3(terrain.x, terrain.y, terrain.z));
            return new Vector3((float)w.x, (float)w.y, (float)w.z);
        }

        /// <summary>A world position (a moved handle) as a control point (terrain x, y, height z).</summary>
        public Vector3 ToTerrain(Vector3 world)
        {
            Double3 t = _frame.WorldToTerrain(new Double3(world.x, world.y, world.z));
            return new Vector3((float)t.x, (float)t.y, (float)t.z);
        }
    }
}
