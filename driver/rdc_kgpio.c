// SPDX-License-Identifier: GPL-2.0-only
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * The RDC-1's four pins as Linux GPIO lines: one gpio_chip per device,
 * labelled "DEVICE-pins" (rdcfb.N-pins, rdcdrm.N-pins), lines TE, IRQ,
 * RESET_N and BL_EN; rdcfb.ko and rdcdrm.ko both link this file.
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

#include "rdc_kchip.h"

#if IS_ENABLED(CONFIG_GPIOLIB_IRQCHIP)

/* Line offsets are the bit numbers of the PINS register. */
enum {
	RDC_KGPIO_LINE_TE,
	RDC_KGPIO_LINE_IRQ,
	RDC_KGPIO_LINE_RESET_N,
	RDC_KGPIO_LINE_BL_EN,
	RDC_KGPIO_LINES,
};

#define RDC_KGPIO_PINS_HOST_IN	(RDC_PIN_TE | RDC_PIN_IRQ)
#define RDC_KGPIO_PINS_HOST_OUT (RDC_PIN_RESET_N | RDC_PIN_BL_EN)
/* Pin changes waiting for delivery (a power of two). */
#define RDC_KGPIO_PIN_QUEUE 256u

static const char *const rdc_kgpio_line_names[RDC_KGPIO_LINES] = {
	[RDC_KGPIO_LINE_TE] = "TE",
	[RDC_KGPIO_LINE_IRQ] = "IRQ",
	[RDC_KGPIO_LINE_RESET_N] = "RESET_N",
	[RDC_KGPIO_LINE_BL_EN] = "BL_EN",
};

/* Chips unbound under a consumer's interrupt, freed at module exit. */
static LIST_HEAD(rdc_kgpio_kept);
static DEFINE_MUTEX(rdc_kgpio_kept_lock);

struct rdc_kgpio_event {
	ktime_t wall; /* when it happened on the paced clock; 0 stepped */
	u32 levels;   /* TE and IRQ after it */
};

struct rdc_kgpio {
	struct gpio_chip gc;
	struct rdc_kchip *chip;
	char label[32];

	spinlock_t ev_lock; /* the queue and the fields marked ev */
	u64 ev_t0;	    /* ev: when ev_lock was taken */
	struct rdc_kgpio_event ev[RDC_KGPIO_PIN_QUEUE];
	u32 head, count; /* ev */
	u32 live;	 /* ev: TE/IRQ after the last change queued (or lost) */
	u32 shown;	 /* ev: after the last change delivered */
	bool delivering; /* ev: an edge is in a consumer's hands */
	u64 edges;	 /* ev: edges delivered */
	u64 lost;	 /* ev: edges dropped at a full queue */
	u64 late_max_ns, late_sum_ns, late_n; /* ev: delivery after the edge */

	struct irq_domain *domain;
	struct list_head kept;	      /* on rdc_kgpio_kept once unbound */
	u8 irq_type[RDC_KGPIO_LINES]; /* IRQ_TYPE_EDGE_* a consumer asked for */
	struct mutex deliver_lock;    /* one deliverer at a time, in order */
	bool gone; /* deliver_lock: the chip is being removed */
	struct work_struct deliver_work;
};

/* ev_lock, its holds timed with the chip's other interrupts-off sections */
#define rdc_kgpio_ev_lock(g, flags) \
	rdc_kchip_spin_lock(&(g)->ev_lock, flags, (g)->ev_t0)
#define rdc_kgpio_ev_unlock(g, flags) \
	rdc_kchip_spin_unlock(&(g)->ev_lock, flags, (g)->ev_t0, \
			      &(g)->chip->irqoff)

/* ---- Delivery ------------------------------------------------------------ */

/*
 * With chip->lock held, from the trace point: queue a change of TE/IRQ.
 * `wall` is the wall time the paced clock maps its simulated time to.
 */
void rdc_kgpio_event_locked(struct rdc_kgpio *g, ktime_t wall, u32 levels)
{
	unsigned long flags;
	u32 changed;

	levels &= RDC_KGPIO_PINS_HOST_IN;
	rdc_kgpio_ev_lock(g, flags);
	changed = levels ^ g->live;
	if (!changed) {
		rdc_kgpio_ev_unlock(g, flags);
		return;
	}
	g->live = levels;
	if (g->count == RDC_KGPIO_PIN_QUEUE) {
		g->lost += hweight32(changed);
		rdc_kgpio_ev_unlock(g, flags);
		dev_warn_ratelimited(g->gc.parent,
				     "pin events queue full: edges lost\n");
		return;
	}
	g->ev[(g->head + g->count) % RDC_KGPIO_PIN_QUEUE] =
		(struct rdc_kgpio_event){ .wall = wall, .levels = levels };
	g->count++;
	rdc_kgpio_ev_unlock(g, flags);
	queue_work(system_highpri_wq, &g->deliver_work);
}

static void rdc_kgpio_edge(struct rdc_kgpio *g, unsigned int line, bool rising)
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
static void rdc_kgpio_deliver(struct rdc_kgpio *g)
{
	struct rdc_kgpio_event e;
	unsigned long flags;
	unsigned int line;
	u32 changed;
	s64 late;

	mutex_lock(&g->deliver_lock);
	while (!g->gone) {
		rdc_kgpio_ev_lock(g, flags);
		if (!g->count) {
			g->delivering = false;
			rdc_kgpio_ev_unlock(g, flags);
			break;
		}
		e = g->ev[g->head];
		g->head = (g->head + 1) % RDC_KGPIO_PIN_QUEUE;
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
		rdc_kgpio_ev_unlock(g, flags);
		for (line = RDC_KGPIO_LINE_TE; line <= RDC_KGPIO_LINE_IRQ;
		     line++)
			if (changed & BIT(line))
				rdc_kgpio_edge(g, line, e.levels & BIT(line));
	}
	mutex_unlock(&g->deliver_lock);
}

static void rdc_kgpio_deliver_work(struct work_struct *work)
{
	rdc_kgpio_deliver(container_of(work, struct rdc_kgpio, deliver_work));
}

/* From the pacing work, right after a slice: no detour through a worker. */
void rdc_kgpio_deliver_now(struct rdc_kgpio *g)
{
	if (g && READ_ONCE(g->count))
		rdc_kgpio_deliver(g);
}

/* ---- gpio_chip ----------------------------------------------------------- */

static int rdc_kgpio_get_direction(struct gpio_chip *gc, unsigned int off)
{
	return BIT(off) & RDC_KGPIO_PINS_HOST_IN ? GPIO_LINE_DIRECTION_IN :
						   GPIO_LINE_DIRECTION_OUT;
}

/* The lines' directions are the chip's: TE and IRQ cannot be driven. */
static int rdc_kgpio_direction_input(struct gpio_chip *gc, unsigned int off)
{
	return BIT(off) & RDC_KGPIO_PINS_HOST_IN ? 0 : -EPERM;
}

static int rdc_kgpio_get(struct gpio_chip *gc, unsigned int off)
{
	struct rdc_kgpio *g = gpiochip_get_data(gc);
	unsigned long flags;
	u32 v;

	if (!(BIT(off) & RDC_KGPIO_PINS_HOST_IN))
		return !!(rdc_kchip_pins_in(g->chip) & BIT(off));
	rdc_kgpio_ev_lock(g, flags);
	v = g->count || g->delivering ? g->shown : g->live;
	rdc_kgpio_ev_unlock(g, flags);
	return !!(v & BIT(off));
}

static void rdc_kgpio_set(struct gpio_chip *gc, unsigned int off, int val)
{
	struct rdc_kgpio *g = gpiochip_get_data(gc);

	if (BIT(off) & RDC_KGPIO_PINS_HOST_OUT)
		rdc_kchip_set_pin(g->chip, BIT(off), val);
}

static int rdc_kgpio_direction_output(struct gpio_chip *gc, unsigned int off,
				      int val)
{
	if (!(BIT(off) & RDC_KGPIO_PINS_HOST_OUT))
		return -EPERM;
	rdc_kgpio_set(gc, off, val);
	return 0;
}

/* ---- irq_chip: edges only, on TE and IRQ --------------------------------- */

/* The chip data is the gpio_chip, as gpiochip_irq_reqres wants it. */
static struct rdc_kgpio *rdc_kgpio_of_irq(struct irq_data *d)
{
	return container_of(irq_data_get_irq_chip_data(d), struct rdc_kgpio,
			    gc);
}

static void rdc_kgpio_irq_mask(struct irq_data *d)
{
	gpiochip_disable_irq(irq_data_get_irq_chip_data(d), irqd_to_hwirq(d));
}

static void rdc_kgpio_irq_unmask(struct irq_data *d)
{
	gpiochip_enable_irq(irq_data_get_irq_chip_data(d), irqd_to_hwirq(d));
}

static int rdc_kgpio_irq_set_type(struct irq_data *d, unsigned int type)
{
	struct rdc_kgpio *g = rdc_kgpio_of_irq(d);

	type &= IRQ_TYPE_SENSE_MASK;
	if (type & ~IRQ_TYPE_EDGE_BOTH)
		return -EINVAL;
	WRITE_ONCE(g->irq_type[irqd_to_hwirq(d)], type);
	return 0;
}

static const struct irq_chip rdc_kgpio_irqchip = {
	.name = "rdc-pins",
	.irq_mask = rdc_kgpio_irq_mask,
	.irq_unmask = rdc_kgpio_irq_unmask,
	.irq_set_type = rdc_kgpio_irq_set_type,
	.flags = IRQCHIP_IMMUTABLE | IRQCHIP_SKIP_SET_WAKE,
	GPIOCHIP_IRQ_RESOURCE_HELPERS,
};

/* Consumers' handlers run nested, in the deliverer's context. */
static int rdc_kgpio_irq_map(struct irq_domain *d, unsigned int irq,
			     irq_hw_number_t hwirq)
{
	struct rdc_kgpio *g = d->host_data;

	if (hwirq >= RDC_KGPIO_LINES || !(BIT(hwirq) & RDC_KGPIO_PINS_HOST_IN))
		return -ENXIO;
	irq_set_chip_data(irq, &g->gc);
	irq_set_chip_and_handler(irq, &rdc_kgpio_irqchip, handle_simple_irq);
	irq_set_nested_thread(irq, 1);
	irq_set_noprobe(irq);
	return 0;
}

static void rdc_kgpio_irq_unmap(struct irq_domain *d, unsigned int irq)
{
	irq_set_nested_thread(irq, 0);
	irq_set_chip_and_handler(irq, NULL, NULL);
	irq_set_chip_data(irq, NULL);
}

static const struct irq_domain_ops rdc_kgpio_domain_ops = {
	.map = rdc_kgpio_irq_map,
	.unmap = rdc_kgpio_irq_unmap,
	.xlate = irq_domain_xlate_twocell,
};

/*
 * Has a consumer ever asked for TE's or IRQ's interrupt?  Whether it still
 * holds it cannot be told for sure while its free_irq may be under way.
 */
static bool rdc_kgpio_mapped(struct rdc_kgpio *g)
{
	return irq_find_mapping(g->domain, RDC_KGPIO_LINE_TE) ||
	       irq_find_mapping(g->domain, RDC_KGPIO_LINE_IRQ);
}

static void rdc_kgpio_free(struct rdc_kgpio *g)
{
	unsigned int line, irq;

	for (line = RDC_KGPIO_LINE_TE; line <= RDC_KGPIO_LINE_IRQ; line++) {
		irq = irq_find_mapping(g->domain, line);
		if (irq)
			irq_dispose_mapping(irq);
	}
	irq_domain_remove(g->domain);
	kfree(g);
}

/* ---- Registration -------------------------------------------------------- */

int rdc_kgpio_register(struct rdc_kchip *chip, struct device *dev)
{
	struct rdc_kgpio *g;
	int ret;

	BUILD_BUG_ON(BIT(RDC_KGPIO_LINE_TE) != RDC_PIN_TE ||
		     BIT(RDC_KGPIO_LINE_IRQ) != RDC_PIN_IRQ ||
		     BIT(RDC_KGPIO_LINE_RESET_N) != RDC_PIN_RESET_N ||
		     BIT(RDC_KGPIO_LINE_BL_EN) != RDC_PIN_BL_EN);
	g = kzalloc(sizeof(*g), GFP_KERNEL);
	if (!g)
		return -ENOMEM;
	g->chip = chip;
	spin_lock_init(&g->ev_lock);
	mutex_init(&g->deliver_lock);
	INIT_WORK(&g->deliver_work, rdc_kgpio_deliver_work);
	snprintf(g->label, sizeof(g->label), "%s-pins", dev_name(dev));

	g->gc.label = g->label;
	g->gc.parent = dev;
	g->gc.owner = THIS_MODULE;
	g->gc.base = -1;
	g->gc.ngpio = RDC_KGPIO_LINES;
	g->gc.names = rdc_kgpio_line_names;
	g->gc.get_direction = rdc_kgpio_get_direction;
	g->gc.direction_input = rdc_kgpio_direction_input;
	g->gc.direction_output = rdc_kgpio_direction_output;
	g->gc.get = rdc_kgpio_get;
	g->gc.set = rdc_kgpio_set;
	/* RESET_N and BL_EN take chip->lock, a mutex */
	g->gc.can_sleep = true;

	g->domain = irq_domain_create_linear(dev_fwnode(dev), RDC_KGPIO_LINES,
					     &rdc_kgpio_domain_ops, g);
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
	rdc_kchip_lock(chip);
	g->live = rdc_hw_pins(chip->hw) & RDC_KGPIO_PINS_HOST_IN;
	g->shown = g->live;
	chip->gpio = g;
	rdc_kchip_unlock(chip);
	return 0;
}

/*
 * The queue is stopped before the chip goes.  The module cannot be
 * unloaded while a consumer holds a line (gpiolib pins it); a device
 * unbound under one loses its lines (gpiolib says so), and the chip stays
 * for a consumer's free_irq if its interrupts were ever used.
 */
void rdc_kgpio_unregister(struct rdc_kchip *chip)
{
	struct rdc_kgpio *g;

	rdc_kchip_lock(chip);
	g = chip->gpio;
	chip->gpio = NULL;
	rdc_kchip_unlock(chip);
	if (!g)
		return;
	mutex_lock(&g->deliver_lock);
	g->gone = true;
	mutex_unlock(&g->deliver_lock);
	cancel_work_sync(&g->deliver_work);
	gpiochip_remove(&g->gc);
	if (rdc_kgpio_mapped(g)) {
		mutex_lock(&rdc_kgpio_kept_lock);
		list_add(&g->kept, &rdc_kgpio_kept);
		mutex_unlock(&rdc_kgpio_kept_lock);
		return;
	}
	rdc_kgpio_free(g);
}

/* Every consumer has let go by now: the module's references say so. */
void rdc_kgpio_module_exit(void)
{
	struct rdc_kgpio *g, *tmp;

	mutex_lock(&rdc_kgpio_kept_lock);
	list_for_each_entry_safe(g, tmp, &rdc_kgpio_kept, kept) {
		list_del(&g->kept);
		rdc_kgpio_free(g);
	}
	mutex_unlock(&rdc_kgpio_kept_lock);
}

void rdc_kgpio_stats(struct rdc_kgpio *g, struct rdc_kchip_pin_stats *s)
{
	unsigned long flags;

	memset(s, 0, sizeof(*s));
	if (!g)
		return;
	rdc_kgpio_ev_lock(g, flags);
	s->edges = g->edges;
	s->lost = g->lost;
	s->late_max_ns = g->late_max_ns;
	s->late_avg_ns = g->late_n ? div64_u64(g->late_sum_ns, g->late_n) : 0;
	rdc_kgpio_ev_unlock(g, flags);
}

#endif /* CONFIG_GPIOLIB_IRQCHIP */
