import { useEffect, useEffectEvent, useRef, useState } from 'react';
import 'softface/element';

/**
 * `<SoftFace>`: the `<soft-face>` element as a React component.
 *
 * Its other props go to the element: its attributes (`resolution`, `preset`, `expression`, ...), `id`, `style`.
 * `actionUnits` (`{ AU12: 0.8 }`) are set through the face's handle, and `onReady` gets the handle once the face has
 * started, and again after a new `resolution` or `solver` rebuilt it. Unmounting removes the element, which disposes
 * its face.
 */
export function SoftFace({ actionUnits, onReady, ...attributes }) {
  const element = useRef(null);
  const [face, setFace] = useState();

  // The element tells that its handle is there with `ready`. StrictMode runs this twice on mount, on the same
  // element: the first listener is gone before the second is added.
  useEffect(() => {
    const node = element.current;
    const ready = () => setFace(node.face);
    node.addEventListener('ready', ready);
    return () => node.removeEventListener('ready', ready);
  }, []);

  // Compared by value: a literal `actionUnits={{ AU12: 0.8 }}` is a new object at each render. A new preset or
  // expression attribute sets the face's whole expression, these Action Units too: they are set again after it.
  const units = JSON.stringify(actionUnits ?? {});
  const applied = useRef({});
  useEffect(() => {
    // A new resolution disposes the face at once; its successor's `ready` brings this effect back.
    if (!face || face.isDisposed()) return;
    const next = JSON.parse(units);
    for (const id of Object.keys(applied.current)) if (!(id in next)) face.setActionUnit(id, 0);
    for (const [id, weight] of Object.entries(next)) face.setActionUnit(id, weight);
    applied.current = next;
  }, [face, units, attributes.preset, attributes.expression]);

  // After the effect above, so that the handle it is given already shows the props.
  const announce = useEffectEvent((handle) => onReady?.(handle));
  useEffect(() => {
    if (face) announce(face);
  }, [face]);

  return <soft-face ref={element} {...attributes} />;
}
