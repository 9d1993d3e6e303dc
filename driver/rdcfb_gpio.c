// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The RDC-1's four pins as Linux GPIO lines: one gpio_chip per device,
 * labelled "rdcfb.N-pins", lines TE, IRQ, RESET_N and BL_EN.
 *
 * TE and IRQ are the chip's outputs, so the host's inputs.  Their edges
 * come from the chip's RDC_TRACE_PINS trace point, which fires inside the
 * simulation: under chip->lock, in the middle of a slice of simulated
 * time.  There they only go into a bounded queue (ev_lock: a spinlock held
 * for a few words), in order; a worker (or the pacing work itself,
 * right after the slice that produced them) takes them out and hands each
 * to the GPIO character device through handle_nested_irq, which runs its
 * thread function in the caller's context: one call per edge, so edges
 * that follow each other quickly are neither merged nor lost, and its
 * timestamps follow the delivery order.  While an edge is being delivered
 * the line reads the level that edge left, so a consumer watching both
 * edges reads the right direction.  A full queue drops the edge and
 * counts it (pin_lost in sysfs, and a ratelimited warning).
 *
 * RESET_N and BL_EN are the chip's inputs, so the host's outputs: setting
 * them drives the chip's pins through rdc_hw_set_pins.
 *
 * The interrupt domain is the driver's own, not gpiolib's: gpiolib would
 * dispose of the mappings when the device is unbound, under a consumer
 * that still has its edge interrupt requested (the 6.1 character device
 * cannot give it back), and the consumer's free_irq would then miss them.
 * So a chip whose interrupts were ever mapped is kept, mappings and all,
 * until the module goes, which gpiolib does not let happen before every
 * consumer has let go.
 */
#include <linux/bitops.h>
#include <linux/gpio/driver.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/irqdomain.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/workqueue.h>

#include "rdcfb.h"

#if IS_ENABLED(CONFIG_GPIOLIB_IRQCHIP)

/* Line offsets are the bit numbers of the PINS register. */
enum {
	RDCFB_LINE_TE,
	RDCFB_LINE_IRQ,
	RDCFB_LINE_RESET_N,
	RDCFB_LINE_BL_EN,
	RDCFB_LINES,
};

#define RDCFB_PINS_HOST_IN  (RDC_PIN_TE | RDC_PIN_IRQ)
#define RDCFB_PINS_HOST_OUT (RDC_PIN_RESET_N | RDC_PIN_BL_EN)
/* Pin changes waiting for delivery (a power of two). */
#define RDCFB_PIN_QUEUE 256u

static const char *const rdcfb_line_names[RDCFB_LINES] = {
	[RDCFB_LINE_TE] = "TE",
	[RDCFB_LINE_IRQ] = "IRQ",
	[RDCFB_LINE_RESET_N] = "RESET_N",
	[RDCFB_LINE_BL_EN] = "BL_EN",
};

/* Chips unbound under a consumer's interrupt, freed at module exit. */
static LIST_HEAD(rdcfb_gpio_kept);
static DEFINE_MUTEX(rdcfb_gpio_kept_lock);

struct rdcfb_pin_event {
	ktime_t wall; /* when it happened on the paced clock; 0 stepped */
	u32 levels;   /* TE and IRQ after it */
};

struct rdcfb_gpio {
	struct gpio_chip gc;
	struct rdcfb_chip *chip;
	char label[32];

	spinlock_t ev_lock; /* the queue and the fields marked ev */
	u64 ev_t0;	    /* ev: when ev_lock was taken */
	struct rdcfb_pin_event ev[RDCFB_PIN_QUEUE];
	u32 head, count; /* ev */
	u32 live;	 /* ev: TE/IRQ after the last change queued (or lost) */
	u32 shown;	 /* ev: after the last change delivered */
	bool delivering; /* ev: an edge is in a consumer's hands */
	u64 edges;	 /* ev: edges delivered */
	u64 lost;	 /* ev: edges dropped at a full queue */
	u64 late_max_ns, late_sum_ns, late_n; /* ev: delivery after the edge */

	struct irq_domain *domain;
	struct list_head kept;	   /* on rdcfb_gpio_kept once unbound */
	u8 irq_type[RDCFB_LINES];  /* IRQ_TYPE_EDGE_* a consumer asked for */
	struct mutex deliver_lock; /* one deliverer at a time, in order */
	bool gone;		   /* deliver_lock: the chip is being removed */
	struct work_struct deliver_work;
};

/* ev_lock, its holds timed with the chip's other interrupts-off sections */
#define rdcfb_ev_lock(g, flags) \
	rdcfb_spin_lock(&(g)->ev_lock, flags, (g)->ev_t0)
#define rdcfb_ev_unlock(g, flags) \
	rdcfb_spin_unlock(&(g)->ev_lock, flags, (g)->ev_t0, &(g)->chip->irqoff)

/* ---- Delivery ------------------------------------------------------------ */

/*
 * With chip->lock held, from the trace point: queue a change of TE/IRQ.
 * `wall` is the wall time the paced clock maps its simulated time to.
 */
void rdcfb_gpio_event_locked(struct rdcfb_gpio *g, ktime_t wall, u32 levels)
{
	unsigned long flags;
	u32 changed;

	levels &= RDCFB_PINS_HOST_IN;
	rdcfb_ev_lock(g, flags);
	changed = levels ^ g->live;
	if (!changed) {
		rdcfb_ev_unlock(g, flags);
		return;
	}
	g->live = levels;
	if (g->count == RDCFB_PIN_QUEUE) {
		g->lost += hweight32(changed);
		rdcfb_ev_unlock(g, flags);
		dev_warn_ratelimited(g->gc.parent,
				     "pin events queue full: edges lost\n");
		return;
	}
	g->ev[(g->head + g->count) % RDCFB_PIN_QUEUE] =
		(struct rdcfb_pin_event){ .wall = wall, .levels = levels };
	g->count++;
	rdcfb_ev_unlock(g, flags);
	queue_work(system_highpri_wq, &g->deliver_work);
}

static void rdcfb_gpio_edge(struct rdcfb_gpio *g, unsigned int line,
			    bool rising)
{
	u8 type = READ_ONCE(g->irq_type[line]);
	unsigned int irq;

	if (!(type & (rising ? IRQ_TYPE_EDGE_RISING : IRQ_TYPE_EDGE_FALLING)))
		return;
	irq = irq_find_mapping(g->domain, line);
	if (irq)
		handle_nested_irq(irq);
}

/* Hand every queued change to the consumers, in order (process context). */
static void rdcfb_gpio_deliver(struct rdcfb_gpio *g)
{
	struct rdcfb_pin_event e;
	unsigned long flags;
	unsigned int line;
	u32 changed;
	s64 late;

	mutex_lock(&g->deliver_lock);
	while (!g->gone) {
		rdcfb_ev_lock(g, flags);
		if (!g->count) {
			g->delivering = false;
			rdcfb_ev_unlock(g, flags);
			break;
		}
		e = g->ev[g->head];
		g->head = (g->head + 1) % RDCFB_PIN_QUEUE;
		g->count--;
		changed = e.levels ^ g->shown;
		g->shown = e.levels;
		g->delivering = true;
		g->edges += hweight32(changed);
		if (e.wall) {
			late = ktime_to_ns(ktime_sub(ktime_get(), e.wall));
			late = max_t(s64, late, 0);
			g->late_max_ns = max_t(u64, g->late_max_ns, late);
			g->late_sum_ns += late;
			g->late_n++;
		}
		rdcfb_ev_unlock(g, flags);
		for (line = RDCFB_LINE_TE; line <= RDCFB_LINE_IRQ; line++)
			if (changed & BIT(line))
				rdcfb_gpio_edge(g, line, e.levels & BIT(line));
	}
	mutex_unlock(&g->deliver_lock);
}

static void rdcfb_gpio_deliver_work(struct work_struct *work)
{
	rdcfb_gpio_deliver(container_of(work, struct rdcfb_gpio, deliver_work));
}

/* From the pacing work, right after a slice: no detour through a worker. */
void rdcfb_gpio_deliver_now(struct rdcfb_gpio *g)
{
	if (g && READ_ONCE(g->count))
		rdcfb_gpio_deliver(g);
}

/* ---- gpio_chip ----------------------------------------------------------- */

static int rdcfb_gpio_get_direction(struct gpio_chip *gc, unsigned int off)
{
	return BIT(off) & RDCFB_PINS_HOST_IN ? GPIO_LINE_DIRECTION_IN :
					       GPIO_LINE_DIRECTION_OUT;
}

/* The lines' directions are the chip's: TE and IRQ cannot be driven. */
static int rdcfb_gpio_direction_input(struct gpio_chip *gc, unsigned int off)
{
	return BIT(off) & RDCFB_PINS_HOST_IN ? 0 : -EPERM;
}

static int rdcfb_gpio_get(struct gpio_chip *gc, unsigned int off)
{
	struct rdcfb_gpio *g = gpiochip_get_data(gc);
	unsigned long flags;
	u32 v;

	if (!(BIT(off) & RDCFB_PINS_HOST_IN))
		return !!(rdcfb_chip_pins_in(g->chip) & BIT(off));
	rdcfb_ev_lock(g, flags);
	v = g->count || g->delivering ? g->shown : g->live;
	rdcfb_ev_unlock(g, flags);
	return !!(v & BIT(off));
}

static void rdcfb_gpio_set(struct gpio_chip *gc, unsigned int off, int val)
{
	struct rdcfb_gpio *g = gpiochip_get_data(gc);

	if (BIT(off) & RDCFB_PINS_HOST_OUT)
		rdcfb_chip_set_pin(g->chip, BIT(off), val);
}

static int rdcfb_gpio_direction_output(struct gpio_chip *gc, unsigned int off,
				       int val)
{
	if (!(BIT(off) & RDCFB_PINS_HOST_OUT))
		return -EPERM;
	rdcfb_gpio_set(gc, off, val);
	return 0;
}

/* ---- irq_chip: edges only, on TE and IRQ --------------------------------- */

/* The chip data is the gpio_chip, as gpiochip_irq_reqres wants it. */
static struct rdcfb_gpio *rdcfb_gpio_of_irq(struct irq_data *d)
{
	return container_of(irq_data_get_irq_chip_data(d), struct rdcfb_gpio,
			    gc);
}

static void rdcfb_gpio_irq_mask(struct irq_data *d)
{
	gpiochip_disable_irq(irq_data_get_irq_chip_data(d), irqd_to_hwirq(d));
}

static void rdcfb_gpio_irq_unmask(struct irq_data *d)
{
	gpiochip_enable_irq(irq_data_get_irq_chip_data(d), irqd_to_hwirq(d));
}

static int rdcfb_gpio_irq_set_type(struct irq_data *d, unsigned int type)
{
	struct rdcfb_gpio *g = rdcfb_gpio_of_irq(d);

	type &= IRQ_TYPE_SENSE_MASK;
	if (type & ~IRQ_TYPE_EDGE_BOTH)
		return -EINVAL;
	WRITE_ONCE(g->irq_type[irqd_to_hwirq(d)], type);
	return 0;
}

static const struct irq_chip rdcfb_gpio_irqchip = {
	.name = "rdcfb-pins",
	.irq_mask = rdcfb_gpio_irq_mask,
	.irq_unmask = rdcfb_gpio_irq_unmask,
	.irq_set_type = rdcfb_gpio_irq_set_type,
	.flags = IRQCHIP_IMMUTABLE | IRQCHIP_SKIP_SET_WAKE,
	GPIOCHIP_IRQ_RESOURCE_HELPERS,
};

/* Consumers' handlers run nested, in the deliverer's context. */
static int rdcfb_gpio_irq_map(struct irq_domain *d, unsigned int irq,
			      irq_hw_number_t hwirq)
{
	struct rdcfb_gpio *g = d->host_data;

	if (hwirq >= RDCFB_LINES || !(BIT(hwirq) & RDCFB_PINS_HOST_IN))
		return -ENXIO;
	irq_set_chip_data(irq, &g->gc);
	irq_set_chip_and_handler(irq, &rdcfb_gpio_irqchip, handle_simple_irq);
	irq_set_nested_thread(irq, 1);
	irq_set_noprobe(irq);
	return 0;
}

static void rdcfb_gpio_irq_unmap(struct irq_domain *d, unsigned int irq)
{
	irq_set_nested_thread(irq, 0);
	irq_set_chip_and_handler(irq, NULL, NULL);
	irq_set_chip_data(irq, NULL);
}

static const struct irq_domain_ops rdcfb_gpio_domain_ops = {
	.map = rdcfb_gpio_irq_map,
	.unmap = rdcfb_gpio_irq_unmap,
	.xlate = irq_domain_xlate_twocell,
};

/*
 * Has a consumer ever asked for TE's or IRQ's interrupt?  Whether it still
 * holds it cannot be told for sure while its free_irq may be under way.
 */
static bool rdcfb_gpio_mapped(struct rdcfb_gpio *g)
{
	return irq_find_mapping(g->domain, RDCFB_LINE_TE) ||
	       irq_find_mapping(g->domain, RDCFB_LINE_IRQ);
}

static void rdcfb_gpio_free(struct rdcfb_gpio *g)
{
	unsigned int line, irq;

	for (line = RDCFB_LINE_TE; line <= RDCFB_LINE_IRQ; line++) {
		irq = irq_find_mapping(g->domain, line);
		if (irq)
			irq_dispose_mapping(irq);
	}
	irq_domain_remove(g->domain);
	kfree(g);
}

/* ---- Registration -------------------------------------------------------- */

int rdcfb_gpio_register(struct rdcfb_chip *chip, struct device *dev, int id)
{
	struct rdcfb_gpio *g;
	int ret;

	BUILD_BUG_ON(BIT(RDCFB_LINE_TE) != RDC_PIN_TE ||
		     BIT(RDCFB_LINE_IRQ) != RDC_PIN_IRQ ||
		     BIT(RDCFB_LINE_RESET_N) != RDC_PIN_RESET_N ||
		     BIT(RDCFB_LINE_BL_EN) != RDC_PIN_BL_EN);
	g = kzalloc(sizeof(*g), GFP_KERNEL);
	if (!g)
		return -ENOMEM;
	g->chip = chip;
	spin_lock_init(&g->ev_lock);
	mutex_init(&g->deliver_lock);
	INIT_WORK(&g->deliver_work, rdcfb_gpio_deliver_work);
	snprintf(g->label, sizeof(g->label), RDCFB_NAME ".%d-pins", id);

	g->gc.label = g->label;
	g->gc.parent = dev;
	g->gc.owner = THIS_MODULE;
	g->gc.base = -1;
	g->gc.ngpio = RDCFB_LINES;
	g->gc.names = rdcfb_line_names;
	g->gc.get_direction = rdcfb_gpio_get_direction;
	g->gc.direction_input = rdcfb_gpio_direction_input;
	g->gc.direction_output = rdcfb_gpio_direction_output;
	g->gc.get = rdcfb_gpio_get;
	g->gc.set = rdcfb_gpio_set;
	/* RESET_N and BL_EN take chip->lock, a mutex */
	g->gc.can_sleep = true;

	g->domain = irq_domain_create_linear(dev_fwnode(dev), RDCFB_LINES,
					     &rdcfb_gpio_domain_ops, g);
	if (!g->domain) {
		kfree(g);
		return -ENOMEM;
	}
	ret = gpiochip_add_data(&g->gc, g);
	if (ret) {
		irq_domain_remove(g->domain);
		kfree(g);
		return ret;
	}
	ret = gpiochip_irqchip_add_domain(&g->gc, g->domain);
	if (ret) {
		gpiochip_remove(&g->gc);
		irq_domain_remove(g->domain);
		kfree(g);
		return ret;
	}
	rdcfb_chip_lock(chip);
	g->live = rdc_hw_pins(&chip->hw) & RDCFB_PINS_HOST_IN;
	g->shown = g->live;
	chip->gpio = g;
	rdcfb_chip_unlock(chip);
	return 0;
}

/*
 * The queue is stopped before the chip goes.  The module cannot be
 * unloaded while a consumer holds a line (gpiolib pins it); a device
 * unbound under one loses its lines (gpiolib says so), and the chip stays
 * for a consumer's free_irq if its interrupts were ever used.
 */
void rdcfb_gpio_unregister(struct rdcfb_chip *chip)
{
	struct rdcfb_gpio *g;

	rdcfb_chip_lock(chip);
	g = chip->gpio;
	chip->gpio = NULL;
	rdcfb_chip_unlock(chip);
	if (!g)
		return;
	mutex_lock(&g->deliver_lock);
	g->gone = true;
	mutex_unlock(&g->deliver_lock);
	cancel_work_sync(&g->deliver_work);
	gpiochip_remove(&g->gc);
	if (rdcfb_gpio_mapped(g)) {
		mutex_lock(&rdcfb_gpio_kept_lock);
		list_add(&g->kept, &rdcfb_gpio_kept);
		mutex_unlock(&rdcfb_gpio_kept_lock);
		return;
	}
	rdcfb_gpio_free(g);
}

/* Every consumer has let go by now: the module's references say so. */
void rdcfb_gpio_module_exit(void)
{
	struct rdcfb_gpio *g, *tmp;

	mutex_lock(&rdcfb_gpio_kept_lock);
	list_for_each_entry_safe(g, tmp, &rdcfb_gpio_kept, kept) {
		list_del(&g->kept);
		rdcfb_gpio_free(g);
	}
	mutex_unlock(&rdcfb_gpio_kept_lock);
}

void rdcfb_gpio_stats(struct rdcfb_gpio *g, struct rdcfb_pin_stats *s)
{
	unsigned long flags;

	memset(s, 0, sizeof(*s));
	if (!g)
		return;
	rdcfb_ev_lock(g, flags);
	s->edges = g->edges;
	s->lost = g->lost;
	s->late_max_ns = g->late_max_ns;
	s->late_avg_ns = g->late_n ? div64_u64(g->late_sum_ns, g->late_n) : 0;
	rdcfb_ev_unlock(g, flags);
}

#endif /* CONFIG_GPIOLIB_IRQCHIP */
