package org.proactiverobotics.engine;

/**
 * Deterministic test rules with state, shared-memory writes, generation and failures, to compare
 * an engine that was stopped and resumed with one that never stopped.
 */
final class Workload {

    private Workload() {
    }

    /** Counts when activated, writes the CommandArray, PriorityArray and values, spawns children and flaky rules. */
    static final class Counter extends Rule {
        String id;
        int slot;
        int count;

        private Counter() {
        }

        Counter(String id, int slot) {
            this.id = id;
            this.slot = slot;
        }

        @Override
        public String scenario() {
            return "counting";
        }

        @Override
        public String name() {
            return "Counter-" + id;
        }

        @Override
        protected boolean activationGuards(RuleContext ctx) {
            return ctx.iteration() % 5 != 0;
        }

        @Override
        protected boolean conditions(RuleContext ctx) {
            return (count + ctx.iteration()) % 3 != 0;
        }

        @Override
        protected void actions(RuleContext ctx) {
            count++;
            ctx.memory().commandArray().enter(slot, "C " + id + " " + count, scenario(), ctx.iteration());
            ctx.memory().priorityArray().set(slot, count % 4);
            ctx.memory().values().put(id, Integer.toString(count));
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
            if (outcome.conditionsHeld() && count % 4 == 0) {
                ctx.generate(new Child(id + "." + count, 2));
            }
            if (ctx.iteration() % 7 == 2) {
                ctx.generate(new Flaky(id));
            }
        }
    }

    /** Lives ttl iterations. */
    static final class Child extends Rule {
        String id;
        int ttl;
        double weight = Double.NaN;

        private Child() {
        }

        Child(String id, int ttl) {
            this.id = id;
            this.ttl = ttl;
        }

        @Override
        public String scenario() {
            return "counting";
        }

        @Override
        protected void actions(RuleContext ctx) {
            ttl--;
            weight = ttl / 3.0;
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            if (ttl > 0) {
                ctx.generate(this);
            }
        }
    }

    /** Always fails in its actions. */
    static final class Flaky extends Rule {
        String of;

        private Flaky() {
        }

        Flaky(String of) {
            this.of = of;
        }

        @Override
        public String scenario() {
            return "flaky";
        }

        @Override
        protected void actions(RuleContext ctx) {
            throw new IllegalStateException("flaky " + of);
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }

    /** Sums the failures it sees (the previous iteration's and this one's so far): a fail-safe's view. */
    static final class FailureCounter extends Rule {
        int seen;

        @Override
        public String scenario() {
            return "failsafe";
        }

        @Override
        protected void actions(RuleContext ctx) {
            seen += ctx.failures().size();
            ctx.memory().values().put("failuresSeen", Integer.toString(seen));
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }
}
