using System;
using System.Collections.Generic;

namespace GregoryTerrain
{
    /// <summary>
    /// A prefab instance or variant saved with the renderer's flat settings overrides them on their old
    /// paths (<c>tiles</c>): the load moves the value, but the Inspector, Apply and Revert see the override
    /// only on the path now (<c>tessellation.tiles</c>). This renames those modifications by
    /// <see cref="FlatSettingsUpgrade.Paths"/>, on the renderer's targets only.
    /// </summary>
    internal static class OverridePathUpgrade
    {
        /// <summary>
        /// <paramref name="mods"/> with each old renderer path renamed, or null when none is old.
        /// An old one whose target already overrides the path now is dropped: the new path's value is the later edit.
        /// </summary>
        /// <param name="mods">A prefab instance's modifications, as PrefabUtility gives them.</param>
        /// <param name="rendererTarget">The modification's target when it is a renderer, else null.</param>
        /// <param name="path">The modification's property path.</param>
        /// <param name="renamed">The modification on another path.</param>
        public static List<T> Rewrite<T>(IReadOnlyList<T> mods, Func<T, object> rendererTarget, Func<T, string> path, Func<T, string, T> renamed)
        {
            var taken = new HashSet<(object, string)>();
            foreach (T m in mods)
                if (rendererTarget(m) is object target) taken.Add((target, path(m)));
            var result = new List<T>(mods.Count);
            bool changed = false;
            foreach (T m in mods)
            {
                object target = rendererTarget(m);
                string now = target == null ? null : FlatSettingsUpgrade.PathNow(path(m));
                if (now == null) { result.Add(m); continue; }
                changed = true;
                if (taken.Add((target, now))) result.Add(renamed(m, now));
            }
            return changed ? result : null;
        }
    }
}
