import { ACTION_UNITS } from '../src/core/expression/facs';
import { describeHighSettles } from './fixtures/high-settles';

// The brows', lids', head's and eyes' Action Units on the high head not settled elsewhere (AU4, AU6, AU9 and AU1 with
// AU2 in tests/wrinkles-high-no-crumpling.test.ts, AU43 and AU46 in tests/expressions-settle-high-lids.test.ts; AU45
// is AU43's muscles, frame for frame). The head's turns (AU51 to AU58) pull the neck's skin; the eyes' turns (AU61 to
// AU66) carry the lids.
const HEAD_AND_EYES = ACTION_UNITS.filter((unit) => unit.number >= 51).map((unit) => unit.id);
describeHighSettles('the upper face, the head and the eyes', [
  'AU1',
  'AU2',
  'AU5',
  'AU7',
  'AU38',
  'AU39',
  'AU41',
  'AU42',
  'AU44',
  ...HEAD_AND_EYES,
]);
