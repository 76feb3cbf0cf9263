/* SPDX-License-Identifier: MIT */
/* gpio_debounce: bounces within the window dropped, changes after it kept. */
#include "gpio_debounce.h"
#include "test.h"

#define MS 1000u

int main(void)
{
	struct gpio_debounce d;

	/* the first change is always accepted */
	gpio_debounce_init(&d, false, 20 * MS);
	CHECK(gpio_debounce_edge(&d, true, 5 * MS));
	CHECK(d.pressed);
	/* a bounce: release and press again within 20 ms of the press */
	CHECK(!gpio_debounce_edge(&d, false, 6 * MS));
	CHECK(!gpio_debounce_edge(&d, true, 7 * MS));
	CHECK(!gpio_debounce_edge(&d, false, 24 * MS + 999));
	CHECK(d.pressed);
	/* the same state again is no change */
	CHECK(!gpio_debounce_edge(&d, true, 100 * MS));
	/* exactly the window after the last accepted change: accepted */
	CHECK(gpio_debounce_edge(&d, false, 120 * MS));
	CHECK(!d.pressed);
	/* the window counts from the last accepted change, not the last edge */
	CHECK(!gpio_debounce_edge(&d, true, 130 * MS));
	CHECK(gpio_debounce_edge(&d, true, 140 * MS));

	/* a typical bouncy press: 5 edges within 3 ms, then a release 200 ms later */
	gpio_debounce_init(&d, false, 20 * MS);
	{
		static const struct {
			bool v;
			uint64_t t;
			bool accepted;
		} edges[] = {
			{ true, 1000 * MS, true },	{ false, 1000 * MS + 300, false },
			{ true, 1000 * MS + 900, false}, { false, 1001 * MS + 500, false },
			{ true, 1002 * MS + 700, false}, { false, 1200 * MS, true },
			{ true, 1200 * MS + 400, false}, { false, 1200 * MS + 800, false },
		};
		int presses = 0, releases = 0;

		for (size_t i = 0; i < sizeof(edges) / sizeof(edges[0]); i++) {
			bool a = gpio_debounce_edge(&d, edges[i].v, edges[i].t);

			CHECK_INT(a, edges[i].accepted);
			presses += a && edges[i].v;
			releases += a && !edges[i].v;
		}
		CHECK_INT(presses, 1);
		CHECK_INT(releases, 1);
		CHECK(!d.pressed);
	}

	/* no debounce: every change counts, even at the same time */
	gpio_debounce_init(&d, true, 0);
	CHECK(gpio_debounce_edge(&d, false, 10));
	CHECK(gpio_debounce_edge(&d, true, 10));
	CHECK(!gpio_debounce_edge(&d, true, 10));

	/* a clock that jumps back does not lock the button */
	gpio_debounce_init(&d, false, 20 * MS);
	CHECK(gpio_debounce_edge(&d, true, 1000 * MS));
	CHECK(gpio_debounce_edge(&d, false, 5 * MS));
	CHECK(!gpio_debounce_edge(&d, true, 10 * MS));
	CHECK(gpio_debounce_edge(&d, true, 25 * MS));
	return 0;
}
