// The page's own script, as a host would write it: the standalone module from the host's own folder.
import * as softface from './lib/softface.standalone.js';

window.softface = softface;
document.documentElement.dataset.state = 'ready';
