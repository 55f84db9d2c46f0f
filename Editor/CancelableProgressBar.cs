using System;
using System.Threading;
using UnityEditor;

namespace GregoryTerrain.EditorTools
{
    /// <summary>
    /// Long editor work's progress on Unity's progress bar; its Cancel button cancels the token.
    /// Report from the main thread (the bar requires it); clear the bar when the work ends.
    /// </summary>
    internal sealed class CancelableProgressBar : IProgress<float>
    {
        readonly string _title, _info;
        readonly CancellationTokenSource _cancel;

        /// <param name="title">The bar's title.</param>
        /// <param name="cancel">Cancelled when the user presses Cancel.</param>
        /// <param name="info">The line under the title; null shows the fraction done.</param>
        public CancelableProgressBar(string title, CancellationTokenSource cancel, string info = null)
        {
            _title = title; _cancel = cancel; _info = info;
        }

        public void Report(float value)
        {
            if (EditorUtility.DisplayCancelableProgressBar(_title, _info ?? $"{value:P0}", value)) _cancel.Cancel();
        }
    }
}
