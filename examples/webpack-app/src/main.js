// The library, imported the ordinary way: the head models, the rig and the lighting come with it (webpack emits them
// into the build), and nothing needs configuring.
import { createFace } from 'softface';
import 'softface/element';

const face = await createFace(document.getElementById('face'), { resolution: 'low' });
face.setActionUnit('AU12', 0.8);
window.face = face;
document.documentElement.dataset.state = 'ready';
