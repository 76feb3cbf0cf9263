// SPDX-License-Identifier: MIT
/*
 * ez-tree 1.1.0 (npm @dgreenheck/ez-tree, on three.js 0.167.1) timed under node, for
 * bench/bench_generate's comparison with edaha's generated trees. tools/setup-eztree.sh
 * installs both, pinned, into node_modules beside this file.
 *
 *   node bench.mjs [--reps N] [--warmup N] [LABEL=TRIANGLES ...]
 *
 * For each LABEL (5k, 20k, 100k; default: all three at 5000, 20000, 100000) it takes
 * that size's ez-tree preset below, sets leaves.count so that the tree's triangles come
 * nearest TRIANGLES, and times Tree.generate(): ez-tree's whole path from options to
 * three.js geometry (branches, leaves, their buffers and materials), as edaha's
 * gen_build + tree_mesh_build is. Median of N runs after the warm-up: at least --warmup runs
 * and WARMUP_S seconds of each tree, as V8 takes 10 to 20 runs to settle. Triangles are
 * those of the index buffers it makes (bark + leaves). Prints, for bench_eztree.c:
 *
 *   eztree-info TEXT
 *   eztree-result LABEL TARGET TRIANGLES BARK LEAVES MEDIAN_S CPU_S REPS OPTIONS...
 *
 * CPU_S is the median CPU time of a run, of the whole process (V8's GC and compiler
 * threads too): on a machine others are using it moves less than the wall time.
 */
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';

/*
 * The one stand-in. ez-tree's textures.js loads its 20 bark and leaf textures when the
 * module is evaluated (new THREE.TextureLoader().load(dataURL)); three's ImageLoader makes
 * an <img> with document.createElementNS and waits for its load event. Node has no DOM:
 * an element that takes listeners and never fires them lets the import finish, with every
 * texture left empty (no image is decoded). Tree.generate() touches nothing else of the
 * browser: it only builds arrays, three.js BufferGeometry and materials.
 */
globalThis.document = {
	createElementNS() {
		return { addEventListener() {}, removeEventListener() {} };
	},
};

const { Tree, TreePreset } = await import('@dgreenheck/ez-tree');

/*
 * The presets closest to a flowering cherry of each size (broadleaved, deciduous) and
 * what is changed besides leaves.count: ez-tree has at most 3 branch levels, so the big
 * tree gets 5 times the trunk's children (boughs) instead of a level more.
 */
const CONFIGS = {
	'5k': { preset: 'Oak Small', target: 5000 },
	'20k': { preset: 'Ash Medium', target: 20000 },
	'100k': { preset: 'Ash Medium', children0: 35, target: 100000 },
};

const WARMUP_S = 1.0;

function version(pkg) {
	const url = new URL(`./node_modules/${pkg}/package.json`, import.meta.url);

	return JSON.parse(readFileSync(url, 'utf8')).version;
}

/* A tree of cfg with leaves.count leaves on each last-level branch (the preset's if undefined). */
function makeTree(cfg, leafCount) {
	const tree = new Tree();

	// what Tree.loadPreset does, without its generate()
	tree.options.copy(structuredClone(TreePreset[cfg.preset]));
	if (cfg.children0 !== undefined) tree.options.branch.children[0] = cfg.children0;
	if (leafCount !== undefined) tree.options.leaves.count = leafCount;
	return tree;
}

function triangles(tree) {
	const bark = tree.branches.indices.length / 3, leaves = tree.leaves.indices.length / 3;

	return { bark, leaves, total: tree.triangleCount };
}

/* The leaves.count whose tree comes nearest target: the leaves' triangles are affine in it
 * (4 a leaf, double billboards) and the branches' do not depend on it. */
function matchLeaves(cfg, target) {
	const t0 = makeTree(cfg, 0), t1 = makeTree(cfg, 1);

	t0.generate();
	t1.generate();
	const a = triangles(t0).total, per = triangles(t1).total - a;

	return Math.max(0, Math.round((target - a) / per));
}

function median(v) {
	const s = [...v].sort((x, y) => x - y), m = s.length >> 1;

	return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

function parseArgs(argv) {
	const o = { reps: 15, warmup: 10, sizes: [] };

	for (let i = 0; i < argv.length; i++) {
		const a = argv[i];

		if (a === '--reps' || a === '--warmup') {
			const n = Number(argv[++i]);

			if (!Number.isInteger(n) || n < 1) throw new Error(`${a} wants a positive integer`);
			o[a.slice(2)] = n;
		} else {
			const [label, n] = a.split('=');

			if (!CONFIGS[label] || !(Number(n) > 0))
				throw new Error(`${a}: want LABEL=TRIANGLES, LABEL one of ${Object.keys(CONFIGS)}`);
			o.sizes.push({ label, target: Number(n) });
		}
	}
	if (o.sizes.length === 0)
		o.sizes = Object.entries(CONFIGS).map(([label, c]) => ({ label, target: c.target }));
	return o;
}

function run() {
	const args = parseArgs(process.argv.slice(2));

	console.log(`eztree-info ez-tree ${version('@dgreenheck/ez-tree')}, three ${version('three')}, ` +
		`node ${process.version}; stand-in: document.createElementNS (textures never load)`);
	for (const { label, target } of args.sizes) {
		const cfg = CONFIGS[label];
		const preset = TreePreset[cfg.preset];
		const count = matchLeaves(cfg, target);
		const tree = makeTree(cfg, count);
		const times = [], cpu = [];

		for (let i = 0, t0 = performance.now();
		     i < args.warmup || performance.now() - t0 < WARMUP_S * 1e3; i++)
			tree.generate();
		for (let i = 0; i < args.reps; i++) {
			const c0 = process.cpuUsage(), t0 = performance.now();

			tree.generate();
			times.push(performance.now() - t0);
			const c = process.cpuUsage(c0);
			cpu.push((c.user + c.system) / 1e3);
		}
		const tri = triangles(tree);
		let options = `preset "${cfg.preset}", leaves.count ${count} (preset ${preset.leaves.count})`;

		if (cfg.children0 !== undefined)
			options += `, branch.children[0] ${cfg.children0} (preset ${preset.branch.children[0]})`;
		console.log(`eztree-result ${label} ${target} ${tri.total} ${tri.bark} ${tri.leaves} ` +
			`${(median(times) / 1e3).toExponential(6)} ${(median(cpu) / 1e3).toExponential(6)} ` +
			`${args.reps} ${options}`);
	}
}

try {
	run();
} catch (e) {
	console.error(`bench.mjs: ${e.message}`);
	process.exit(1);
}
