// The HTML report as a reader uses it, in headless Chromium (Debian's /usr/bin/chromium, driven by
// puppeteer-core): the page loads with no console errors, failed requests or network access; a
// table sorts when its header is clicked; the gallery search narrows the cards; a flip toggles a
// sphere between the truth and a model. Saves a screenshot. With --library, the page of a preset
// library: the library table sorts; the first screen holds a few element groups and scrolling
// loads the rest; the search finds an element's pages by symbol ("Au"), common name ("gold") and
// alias ("aluminium") and kinds by name ("consensus"); class labels stay on one line; the page's
// bytes and load times are printed (not asserted: timings are not tests).
// At 1280 and 390 px wide the page does not overflow horizontally; with --top PREFIX the top of the
// page at each width is saved as PREFIX-1280.png and PREFIX-390.png. The report (not the library)
// opens with its summary, shows η on dielectric cards and, with --lookdev, the look-dev sheets.
//   node report.test.mjs --html DIR/index.html --screenshot FILE.png [--top PREFIX] [--library]
//        [--lookdev] [--chromium PATH]
import { existsSync, statSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import puppeteer from 'puppeteer-core';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i > 0 && i + 1 < process.argv.length ? process.argv[i + 1] : fallback;
}

const html = option('--html');
const screenshot = option('--screenshot');
const top = option('--top');
const chromium = option('--chromium', process.env.CHROMIUM || '/usr/bin/chromium');
let failures = 0, passes = 0;

function check(ok, what) {
  console.log(`${ok ? 'ok' : 'FAILED'}: ${what}`);
  if (ok) ++passes; else ++failures;
}

// The values of one column of a table, as the page holds them (data-v, else the text).
async function column(page, tableId, header) {
  return page.$$eval(`#${tableId} tbody tr`, (rows, header) => {
    const ths = Array.from(rows[0].closest('table').tHead.rows[0].cells);
    const i = ths.findIndex((th) => th.textContent.replace(/[\u25B2\u25BC]/g, '').trim() === header);
    return rows.map((r) => {
      const v = r.cells[i].getAttribute('data-v');
      return v === null ? r.cells[i].textContent : v === '' ? null : Number(v);
    });
  }, header);
}

function sorted(values, dir) {
  const nums = values.filter((v) => v !== null);
  for (let i = 1; i < nums.length; ++i) if (dir * (nums[i] - nums[i - 1]) < 0) return false;
  return values.slice(nums.length).every((v) => v === null);  // n/a last
}

const library = process.argv.includes('--library');

async function tableSorts(page) {
  const table = library ? 'library' : 'schlick';
  // A DOM click: images loading above the table move it between a scroll and a mouse click.
  await page.$eval(`#t-${table} > summary`, (s) => s.click());
  // A large table is loaded from its script when its section opens.
  const header = await page.waitForSelector(`#table-${table} thead th:nth-child(4)`, { timeout: 30000 });
  const name = await header.evaluate((th) => th.textContent.trim());
  const before = await column(page, `table-${table}`, name);
  // DOM clicks too: on the library's page the gallery's images load above the table and can move
  // the header between puppeteer's scroll and its mouse click.
  await header.evaluate((th) => th.click());
  const asc = await column(page, `table-${table}`, name);
  check(asc.length === before.length && asc.length > 1 && sorted(asc, 1) && !sorted(before, 1),
        `the ${table} table sorts ascending by ${name} on a header click (${asc.length} rows, ${asc[0]} first)`);
  await header.evaluate((th) => th.click());
  const desc = await column(page, `table-${table}`, name);
  check(sorted(desc, -1) && desc[0] === asc[asc.length - 1],
        `a second click sorts it descending (${desc[0]} first)`);
  const state = await header.evaluate((th) => th.getAttribute('aria-sort'));
  check(state === 'descending', `the header shows the order (aria-sort=${state})`);
}

// The names of the cards shown after typing `query` into the gallery search, once every group
// the search shows has loaded its cards.
async function search(page, query) {
  await page.$eval('#gallery-filter', (g, q) => { g.value = q; g.dispatchEvent(new Event('input')); }, query);
  await page.waitForFunction(() => document.querySelectorAll('.group:not([hidden]) .gallery[data-src]').length === 0,
                             { timeout: 20000 });
  const names = await page.$$eval('.card', (cards) => cards.filter((c) => !c.hidden && !c.closest('[hidden]'))
    .map((c) => ({ id: c.id, name: c.querySelector('h3').firstChild.textContent, cls: c.querySelector('.cls').textContent,
                   kind: Array.from(c.querySelectorAll('.facts dt')).map((d) => d.textContent) })));
  const count = await page.$eval('#gallery-count', (e) => e.textContent);
  return { names, count };
}

// A library page as it loads, before anything scrolls: a few groups' cards, the rest left to load
// as they near the screen.
async function firstScreen(page) {
  const at = await page.evaluate(() => ({
    cards: document.querySelectorAll('.card').length,
    index: JSON.parse(document.getElementById('gallery-index').textContent).length,
    lazy: document.querySelectorAll('.gallery[data-src]').length,
    groups: Array.from(document.querySelectorAll('.group > h3')).map((h) => h.firstChild.textContent.trim()),
  }));
  check(at.lazy > 0 && at.cards < at.index, `the first screen holds ${at.cards} of ${at.index} cards; ${at.lazy} groups load later (groups: ${at.groups.join(', ')})`);
  return at;
}

// The search finds an element by symbol, common name and alias, kinds by their name only;
// scrolling down loads every group.
async function libraryGallery(page, at) {
  for (const [query, book] of [['gold', 'main/Au/'], ['Au', 'main/Au/'], ['aluminium', 'main/Al/']]) {
    const r = await search(page, query);
    const pages = await page.evaluate((b) => JSON.parse(document.getElementById('gallery-index').textContent)
      .filter((e) => e[0].startsWith('m-' + b.replace(/\//g, '_'))).length, book);
    const all = r.names.every((n) => n.id.startsWith('m-' + book.replace(/\//g, '_')));
    check(r.names.length > 1 && all && r.names.length === pages, `search "${query}" shows ${r.names.length} cards, the ${pages} of ${book} ("${r.count}"; ${r.names.slice(0, 4).map((n) => n.name).join(', ')}, …)`);
    console.log(`search ${query}: ${r.count}; ${r.names.map((n) => n.name).join(', ')}`);
  }
  const c = await search(page, 'consensus');
  check(c.names.length > 0 && c.names.length < at.index / 4 && c.names.every((n) => n.kind.includes('consensus')),
        `search "consensus" shows the ${c.names.length} consensus cards only ("${c.count}")`);
  await search(page, '');
  await page.evaluate(() => window.scrollTo(0, document.scrollingElement.scrollHeight));
  await page.waitForFunction(() => { window.scrollTo(0, document.scrollingElement.scrollHeight); return document.querySelectorAll('.gallery[data-src]').length === 0; },
                             { timeout: 20000, polling: 200 });
  const loaded = await page.$$eval('.card', (cards) => cards.length);
  check(loaded === at.index, `scrolling down loads every group (${loaded} of ${at.index} cards)`);
  const labels = await page.$$eval('.card .cls', (ls) => ls.map((l) => l.getClientRects().length));
  check(labels.every((n) => n === 1), `every class label sits on one line (${labels.length} labels)`);
}

async function galleryFilters(page) {
  const visible = () => page.$$eval('.card', (cards) => cards.filter((c) => !c.hidden).length);
  const total = await visible();
  const [query, expected] = library ? ['main/Au/', 'main/Au/nk/Johnson'] : ['gold', 'Gold'];
  await page.type('#gallery-filter', query);
  const narrowed = await visible();
  const names = await page.$$eval('.card', (cards) => cards.filter((c) => !c.hidden).map((c) => c.querySelector('h3').firstChild.textContent));
  const count = await page.$eval('#gallery-count', (e) => e.textContent);
  // A card matches by its search text (name, source, class): the library's consensus card is
  // named by the element ("Gold") and found by its source (main/Au/consensus).
  const searched = await page.$$eval('.card', (cards) => cards.filter((c) => !c.hidden).map((c) => c.getAttribute('data-search')));
  const others = searched.filter((s) => !s.toLowerCase().includes(query.toLowerCase()));
  check(total > 1 && narrowed >= 1 && narrowed < total && names.includes(expected) && (!library || others.length === 0),
        `the gallery search "${query}" narrows ${total} cards to ${narrowed} (${names.slice(0, 8).join(', ')}` +
        `${names.length > 8 ? ', …' : ''}; "${count}")`);
}

async function flipToggles(page) {
  const flip = '#m-gold .flip';
  const state = () => page.$eval(flip, (f) => ({
    frame: f.getAttribute('data-frame'),
    position: f.querySelector('.flip-img').style.backgroundPosition,
    label: f.querySelector('.flip-label').textContent,
  }));
  const start = await state();
  await page.click(`${flip} .flip-img`);
  const flipped = await state();
  check(start.frame === '0' && flipped.frame !== '0' && flipped.position !== start.position,
        `a click flips the gold sphere from "${start.label}" (${start.position}) to "${flipped.label}" (${flipped.position})`);
  await page.click(`${flip} .flip-img`);
  const back = await state();
  check(back.frame === '0' && back.position === start.position, `a second click flips it back to "${back.label}"`);
  await page.click(`${flip} button[data-frame="2"]`);
  const chosen = await state();
  check(chosen.frame === '2', `choosing a model shows it ("${chosen.label}")`);
  const loaded = await page.$eval(`${flip} .flip-img`, (e) => new Promise((resolve) => {
    const img = new Image();
    img.onload = () => resolve(img.naturalWidth);
    img.onerror = () => resolve(0);
    img.src = e.style.backgroundImage.replace(/^url\(["']?/, '').replace(/["']?\)$/, '');
  }));
  check(loaded > 0, `the flip's image loads (${loaded} px wide)`);
}

// No horizontal overflow at either width (the whole document, every section open); the top of the
// page saved at each width when --top is given.
async function widths(page) {
  await page.$eval('#gallery-filter', (g) => { g.value = ''; g.dispatchEvent(new Event('input')); });
  for (const width of [1280, 390]) {
    await page.setViewport({ width, height: 900 });
    await page.evaluate(() => document.querySelectorAll('details').forEach((d) => { d.open = true; }));
    const m = await page.evaluate(() => {
      const inner = window.innerWidth, scroll = document.scrollingElement.scrollWidth;
      const wide = Array.from(document.querySelectorAll('body *')).filter((e) => {
        const r = e.getBoundingClientRect();
        return r.width > 0 && r.right > inner + 1 && !e.closest('.tablewrap, .flip');
      }).slice(0, 5).map((e) => `${e.tagName.toLowerCase()}.${e.className} ${Math.round(e.getBoundingClientRect().right)}`);
      return { inner, scroll, wide };
    });
    check(m.scroll <= m.inner, `at ${width} px wide nothing overflows horizontally (scrollWidth ${m.scroll}, innerWidth ${m.inner}` +
          `${m.wide.length ? `; too wide: ${m.wide.join(', ')}` : ''})`);
    await page.evaluate(() => document.querySelectorAll('details').forEach((d) => { d.open = false; }));
    if (top) {
      await page.evaluate(() => window.scrollTo(0, 0));
      await page.screenshot({ path: `${top}-${width}.png` });
      console.log(`screenshot: ${top}-${width}.png`);
    }
  }
  await page.setViewport({ width: 1280, height: 1000 });
}

// The summary's lines, η on every dielectric card, and the look-dev sheets when they are expected.
async function structure(page) {
  const lines = await page.$$eval('#summary li', (li) => li.map((l) => l.textContent));
  check(lines.length === 5 && /Best model per class/.test(lines[0]) && /talk's Schlick/.test(lines[1]) && /front/.test(lines[4]),
        `the summary has five findings (${lines.map((l) => l.slice(0, 40)).join(' | ')})`);
  const cards = await page.$$eval('.card', (cs) => cs.map((c) => ({
    cls: c.querySelector('.cls').textContent,
    eta: Array.from(c.querySelectorAll('.facts dt')).some((dt) => dt.textContent.startsWith('η')),
  })));
  const dielectrics = cards.filter((c) => c.cls === 'dielectric');
  check(dielectrics.length > 0 && dielectrics.every((c) => c.eta) && cards.filter((c) => c.eta).length === dielectrics.length,
        `every dielectric card (${dielectrics.length}) and no metal card shows η`);
  if (process.argv.includes('--lookdev')) {
    const widthsLoaded = await page.$$eval('#lookdev img', (imgs) => Promise.all(imgs.map((i) => { i.loading = 'eager'; return i.decode().then(() => i.naturalWidth, () => 0); })));
    check(widthsLoaded.length > 0 && widthsLoaded.every((w) => w > 0),
          `the look-dev section shows ${widthsLoaded.length} sheets, every one loading (${widthsLoaded.join(', ')} px wide)`);
  }
}

async function main() {
  if (!html || !existsSync(html)) throw new Error(`no report at ${html} (pass --html DIR/index.html)`);
  if (!existsSync(chromium)) throw new Error(`no Chromium at ${chromium}: scripts/setup.sh installs Debian's chromium`);
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--no-first-run'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 1000 });
    const errors = [];
    page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
    page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
    await page.setRequestInterception(true);
    page.on('request', (r) => {
      if (r.url().startsWith('file:') || r.url().startsWith('data:')) return r.continue();
      errors.push(`network request: ${r.url()}`);
      return r.abort();
    });
    await page.goto(pathToFileURL(html).href, { waitUntil: 'load' });
    const title = await page.title();
    check(errors.length === 0 && title.length > 0, `"${title}" loads with no console errors, failed or network requests` +
          (errors.length ? `: ${errors.join('; ')}` : ''));
    // Every image loaded first, so no lazy image moves a table between a scroll and a click.
    await page.evaluate(() => Promise.all(Array.from(document.images).map((i) => {
      i.loading = 'eager';
      return i.decode().catch(() => {});
    })));
    if (library) {
      const t = await page.evaluate(() => {
        const n = performance.getEntriesByType('navigation')[0];
        const paint = performance.getEntriesByType('paint').find((p) => p.name === 'first-contentful-paint');
        return { dcl: n.domContentLoadedEventEnd, load: n.loadEventEnd, fcp: paint ? paint.startTime : NaN };
      });
      const bytes = statSync(html).size;
      // Informational: a timing the browser did not record (null from NaN) prints as n/a.
      const ms = (v) => (typeof v === 'number' && Number.isFinite(v) ? v.toFixed(0) : 'n/a');
      console.log(`first screen at 1280 px: index.html ${bytes} bytes, first contentful paint ${ms(t.fcp)} ms, ` +
                  `DOMContentLoaded ${ms(t.dcl)} ms, load ${ms(t.load)} ms`);
    }
    const first = library ? await firstScreen(page) : null;
    await tableSorts(page);
    if (library) await libraryGallery(page, first);
    else await galleryFilters(page);
    if (!library) await flipToggles(page);
    if (!library) await structure(page);
    await widths(page);
    check(errors.length === 0, `no errors while using the page${errors.length ? `: ${errors.join('; ')}` : ''}`);
    if (screenshot) {
      await page.evaluate(() => window.scrollTo(0, 0));
      await page.screenshot({ path: screenshot });
      console.log(`screenshot: ${screenshot}`);
    }
  } finally {
    await browser.close();
  }
}

main().then(() => {
  console.log(`${passes} passed, ${failures} failed`);
  process.exit(failures ? 1 : 0);
}, (e) => {
  console.log(`FAILED: ${e.stack}`);
  console.log(`${passes} passed, ${failures + 1} failed`);
  process.exit(1);
});
