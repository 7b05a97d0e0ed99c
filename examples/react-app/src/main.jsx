// A React app showing a face through the `<SoftFace>` component, in StrictMode (which mounts it twice in development).
import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { SoftFace } from './SoftFace.jsx';

/** Keeps the face's handle where a script (or a test) finds it, and says the page is ready. */
function ready(face) {
  window.face = face;
  document.documentElement.dataset.state = 'ready';
}

createRoot(document.getElementById('root')).render(
  <StrictMode>
    <SoftFace
      id="element"
      resolution="low"
      preset="happiness:0.6"
      actionUnits={{ AU12: 0.8 }}
      onReady={ready}
      style={{ width: 480, height: 480 }}
    />
  </StrictMode>,
);
