; foon2pddl, encoding state, level 3: 17 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-6184c1c2)
  (:requirements :strips)
  (:constants
    baking_powder
    bottle
    bowl
    butter
    carton
    egg
    flour
    frying_pan
    heavy_cream
    ladle
    maple_syrup
    milk
    mixing_bowl
    pancake
    pancake_batter
    plate
    salt
    spatula
    stove
    sugar
    whisk
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-cooked ?o)  ; ?o is cooked
    (is-cracked ?o)  ; ?o is cracked
    (is-empty ?o)  ; ?o is empty
    (is-granulated ?o)  ; ?o is granulated
    (is-half-cooked ?o)  ; ?o is half-cooked
    (is-melted ?o)  ; ?o is melted
    (is-off ?o)  ; ?o is off
    (is-on ?o)  ; ?o is on
    (is-powder ?o)  ; ?o is powder
    (is-solid ?o)  ; ?o is solid
    (is-whole ?o)  ; ?o is whole
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (on ?o ?r)  ; ?o on [?r] or {?r}
    (topped ?o ?r)  ; ?o topped [?r] or {?r}
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available heavy_cream)
      (available mixing_bowl)
      (in heavy_cream carton)
      (is-empty mixing_bowl)
    )
    :effect (and
      (contains mixing_bowl heavy_cream)
      (in heavy_cream mixing_bowl)
      (not (in heavy_cream carton))
      (not (is-empty mixing_bowl))
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available mixing_bowl)
      (available sugar)
      (contains mixing_bowl heavy_cream)
      (is-granulated sugar)
    )
    :effect (and
      (contains mixing_bowl sugar)
      (in sugar mixing_bowl)
      (not (is-granulated sugar))
    )
  )

  (:action crack_u17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available egg)
      (is-empty bowl)
      (is-whole egg)
    )
    :effect (and
      (contains bowl egg)
      (in egg bowl)
      (is-cracked egg)
      (not (is-empty bowl))
      (not (is-whole egg))
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (available frying_pan)
      (available stove)
      (is-empty frying_pan)
      (is-off stove)
    )
    :effect (and
      (on frying_pan stove)
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (available stove)
      (is-off stove)
    )
    :effect (and
      (is-on stove)
      (not (is-off stove))
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (available butter)
      (available frying_pan)
      (is-empty frying_pan)
      (is-solid butter)
      (on frying_pan stove)
    )
    :effect (and
      (contains frying_pan butter)
      (in butter frying_pan)
      (not (is-empty frying_pan))
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (available butter)
      (available stove)
      (in butter frying_pan)
      (is-on stove)
      (is-solid butter)
    )
    :effect (and
      (is-melted butter)
      (not (is-solid butter))
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available flour)
      (available mixing_bowl)
      (is-empty mixing_bowl)
      (is-powder flour)
    )
    :effect (and
      (contains mixing_bowl flour)
      (in flour mixing_bowl)
      (not (is-empty mixing_bowl))
      (not (is-powder flour))
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (available baking_powder)
      (available mixing_bowl)
      (available salt)
      (available sugar)
      (contains mixing_bowl flour)
      (is-granulated salt)
      (is-granulated sugar)
      (is-powder baking_powder)
    )
    :effect (and
      (contains mixing_bowl baking_powder)
      (contains mixing_bowl salt)
      (contains mixing_bowl sugar)
      (in baking_powder mixing_bowl)
      (in salt mixing_bowl)
      (in sugar mixing_bowl)
      (not (is-granulated salt))
      (not (is-granulated sugar))
      (not (is-powder baking_powder))
    )
  )

  (:action crack_u31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters ()
    :precondition (and
      (available egg)
      (available mixing_bowl)
      (contains mixing_bowl baking_powder)
      (contains mixing_bowl flour)
      (contains mixing_bowl salt)
      (contains mixing_bowl sugar)
      (is-whole egg)
    )
    :effect (and
      (contains mixing_bowl egg)
      (in egg mixing_bowl)
      (is-cracked egg)
      (not (is-whole egg))
    )
  )

  (:action pour_u32
    ; unit 32: pour from 04-pancakes.foon:42
    ; pour: mixing bowl (contains {baking powder, egg, flour, salt, sugar}), milk (in [carton]) -> mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), milk (in [mixing bowl])
    :parameters ()
    :precondition (and
      (available milk)
      (available mixing_bowl)
      (contains mixing_bowl baking_powder)
      (contains mixing_bowl egg)
      (contains mixing_bowl flour)
      (contains mixing_bowl salt)
      (contains mixing_bowl sugar)
      (in milk carton)
    )
    :effect (and
      (contains mixing_bowl milk)
      (in milk mixing_bowl)
      (not (in milk carton))
    )
  )

  (:action whisk_u33
    ; unit 33: whisk from 04-pancakes.foon:52
    ; whisk: mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), flour (in [mixing bowl]), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixing bowl]), egg (cracked, in [mixing bowl]), milk (in [mixin...
    :parameters ()
    :precondition (and
      (available baking_powder)
      (available egg)
      (available flour)
      (available milk)
      (available mixing_bowl)
      (available salt)
      (available sugar)
      (available whisk)
      (contains mixing_bowl baking_powder)
      (contains mixing_bowl egg)
      (contains mixing_bowl flour)
      (contains mixing_bowl milk)
      (contains mixing_bowl salt)
      (contains mixing_bowl sugar)
      (in baking_powder mixing_bowl)
      (in egg mixing_bowl)
      (in flour mixing_bowl)
      (in milk mixing_bowl)
      (in salt mixing_bowl)
      (in sugar mixing_bowl)
      (is-cracked egg)
    )
    :effect (and
      (available pancake_batter)
      (contains mixing_bowl pancake_batter)
      (contains pancake_batter baking_powder)
      (contains pancake_batter egg)
      (contains pancake_batter flour)
      (contains pancake_batter milk)
      (contains pancake_batter salt)
      (contains pancake_batter sugar)
      (in pancake_batter mixing_bowl)
      (not (contains mixing_bowl baking_powder))
      (not (contains mixing_bowl egg))
      (not (contains mixing_bowl flour))
      (not (contains mixing_bowl milk))
      (not (contains mixing_bowl salt))
      (not (contains mixing_bowl sugar))
    )
  )

  (:action pour_u34
    ; unit 34: pour from 04-pancakes.foon:114
    ; pour: mixing bowl (contains {pancake batter}), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl]), ladle, frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan ...
    :parameters ()
    :precondition (and
      (available butter)
      (available frying_pan)
      (available ladle)
      (available mixing_bowl)
      (available pancake_batter)
      (contains frying_pan butter)
      (contains mixing_bowl pancake_batter)
      (contains pancake_batter baking_powder)
      (contains pancake_batter egg)
      (contains pancake_batter flour)
      (contains pancake_batter milk)
      (contains pancake_batter salt)
      (contains pancake_batter sugar)
      (in butter frying_pan)
      (in pancake_batter mixing_bowl)
      (is-melted butter)
      (on frying_pan stove)
    )
    :effect (and
      (contains frying_pan pancake_batter)
      (in pancake_batter frying_pan)
      (not (in pancake_batter mixing_bowl))
    )
  )

  (:action cook_u35
    ; unit 35: cook from 04-pancakes.foon:135
    ; cook: stove (on), frying pan (contains {butter, pancake batter}, on [stove]), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan]) -> frying pan (contains {pancake}, on [stove]), pancake (half-cooked,...
    :parameters ()
    :precondition (and
      (available frying_pan)
      (available pancake_batter)
      (available stove)
      (contains frying_pan butter)
      (contains frying_pan pancake_batter)
      (contains pancake_batter baking_powder)
      (contains pancake_batter egg)
      (contains pancake_batter flour)
      (contains pancake_batter milk)
      (contains pancake_batter salt)
      (contains pancake_batter sugar)
      (in pancake_batter frying_pan)
      (is-on stove)
      (on frying_pan stove)
    )
    :effect (and
      (available pancake)
      (contains frying_pan pancake)
      (in pancake frying_pan)
      (is-half-cooked pancake)
      (not (contains frying_pan butter))
      (not (contains frying_pan pancake_batter))
    )
  )

  (:action flip_u36
    ; unit 36: flip from 04-pancakes.foon:151
    ; flip: pancake (half-cooked, in [frying pan]), spatula -> pancake (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (available pancake)
      (available spatula)
      (in pancake frying_pan)
      (is-half-cooked pancake)
    )
    :effect (and
      (is-cooked pancake)
      (not (is-half-cooked pancake))
    )
  )

  (:action pick-and-place_u37
    ; unit 37: pick-and-place from 04-pancakes.foon:161
    ; pick-and-place: frying pan (contains {pancake}, on [stove]), pancake (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {pancake}), pancake (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (available frying_pan)
      (available pancake)
      (available plate)
      (available spatula)
      (contains frying_pan pancake)
      (in pancake frying_pan)
      (is-cooked pancake)
      (is-empty plate)
      (on frying_pan stove)
    )
    :effect (and
      (contains plate pancake)
      (on pancake plate)
      (not (in pancake frying_pan))
      (not (is-empty plate))
    )
  )

  (:action pour_u38
    ; unit 38: pour from 04-pancakes.foon:178
    ; pour: plate (contains {pancake}), pancake (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {maple syrup, pancake}), pancake (cooked, on [plate], topped {maple syrup}), maple syrup (on [pancake])
    :parameters ()
    :precondition (and
      (available maple_syrup)
      (available pancake)
      (available plate)
      (contains plate pancake)
      (in maple_syrup bottle)
      (is-cooked pancake)
      (on pancake plate)
    )
    :effect (and
      (contains plate maple_syrup)
      (on maple_syrup pancake)
      (topped pancake maple_syrup)
      (not (in maple_syrup bottle))
    )
  )
)
