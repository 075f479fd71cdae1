// Tests for book_random.h (chapter 06): glibc's rand(), which lays out the book's random scenes.
// Its first numbers from the default seed are the well-known 1804289383, 846930886, ...; on a
// glibc system the test also compares long runs with the C library's own rand().
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "rt/core/book_random.h"

TEST_CASE("book_random: rand() from the default seed begins as glibc's does", "[ch06]") {
    // A generator of another kind (an LCG, PCG32, the word without its shift) begins otherwise.
    rt::book_random draws;
    const std::vector<std::int32_t> glibc = {1804289383, 846930886,  1681692777, 1714636915,
                                             1957747793, 424238335,  719885386,  1649760492,
                                             596516649,  1189641421, 1025202362, 1350490027};
    for (std::size_t i = 0; i < glibc.size(); ++i) {
        CAPTURE(i);
        CHECK(draws.next() == glibc[i]);
    }
}

TEST_CASE("book_random: srand(0) is srand(1), and each seed its own stream", "[ch06]") {
    rt::book_random zero(0), one(1), two(2);
    int differ_one = 0, differ_two = 0;
    for (int i = 0; i < 1000; ++i) {
        const std::int32_t a = zero.next(), b = one.next(), c = two.next();
        if (a != b) ++differ_one;
        if (a != c) ++differ_two;
    }
    CHECK(differ_one == 0);
    CHECK(differ_two > 990);
}

#ifdef __GLIBC__
TEST_CASE("book_random: equals this C library's rand() over long runs from several seeds",
          "[ch06]") {
    for (unsigned seed : {1u, 0u, 42u, 2147483647u, 4294967295u}) {
        std::srand(seed);
        rt::book_random draws(seed);
        int differ = 0;
        for (int i = 0; i < 200000; ++i)
            if (draws.next() != std::rand()) ++differ;
        CAPTURE(seed);
        CHECK(differ == 0);
    }
}
#endif

TEST_CASE("book_random: the book's random_double, random_int and vec3::random", "[ch06]") {
    rt::book_random a, b;
    // random_double() = rand() / (RAND_MAX + 1.0): 1804289383 / 2^31 first.
    CHECK(a.uniform() == 1804289383 / 2147483648.0);
    b.next();
    // random_double(lo, hi) and random_int(lo, hi) = int(random_double(lo, hi + 1)).
    CHECK(a.uniform(2, 5) == 2 + 3 * (846930886 / 2147483648.0));
    b.next();
    CHECK(a.integer(0, 9) == int(10 * (1681692777 / 2147483648.0)));
    b.next();
    // vec3::random(lo, hi) as g++ evaluates it: the z component is drawn first.
    const rt::vec3 v = a.vector(-1, 1);
    const double z = b.uniform(-1, 1), y = b.uniform(-1, 1), x = b.uniform(-1, 1);
    CHECK(v.z() == rt::real(z));
    CHECK(v.y() == rt::real(y));
    CHECK(v.x() == rt::real(x));
    // random_int(0, i) reaches both ends and nothing else.
    rt::book_random c;
    int below = 0, above = 0, low = 0, high = 0;
    for (int k = 0; k < 20000; ++k) {
        const int r = c.integer(0, 3);
        if (r < 0) ++below;
        if (r > 3) ++above;
        if (r == 0) ++low;
        if (r == 3) ++high;
    }
    CHECK(below == 0);
    CHECK(above == 0);
    CHECK(low > 4500);
    CHECK(high > 4500);
}

TEST_CASE("book_random: the layout seed is the default stream's, 1 unless a program sets it",
          "[ch06]") {
    CHECK(rt::book_layout_seed() == 1);
    rt::set_book_layout_seed(7);
    rt::book_random layout, seven(7);
    rt::set_book_layout_seed(1);
    rt::book_random book, one(1);
    for (int k = 0; k < 100; ++k) {
        CHECK(layout.next() == seven.next());
        CHECK(book.next() == one.next());
    }
    // Another seed is another layout.
    rt::set_book_layout_seed(2);
    rt::book_random two;
    rt::set_book_layout_seed(1);
    CHECK(two.next() != rt::book_random(1).next());
}
