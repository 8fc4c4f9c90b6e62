; foon2pddl, encoding state, level 3: 20 of 101 units after relevance pruning
; goal: french toast (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-2627af69)
  (:requirements :strips)
  (:constants
    baking_powder
    bottle
    bowl
    bread
    butter
    carton
    cinnamon
    custard
    egg
    flour
    fork
    french_toast
    frying_pan
    heavy_cream
    maple_syrup
    milk
    mixing_bowl
    plate
    salt
    spatula
    stove
    sugar
    vanilla_extract
    whisk
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-beaten ?o)  ; ?o is beaten
    (is-cooked ?o)  ; ?o is cooked
    (is-cracked ?o)  ; ?o is cracked
    (is-empty ?o)  ; ?o is empty
    (is-granulated ?o)  ; ?o is granulated
    (is-ground ?o)  ; ?o is ground
    (is-liquid ?o)  ; ?o is liquid
    (is-melted ?o)  ; ?o is melted
    (is-off ?o)  ; ?o is off
    (is-on ?o)  ; ?o is on
    (is-powder ?o)  ; ?o is powder
    (is-sliced ?o)  ; ?o is sliced
    (is-solid ?o)  ; ?o is solid
    (is-whole ?o)  ; ?o is whole
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (on ?o ?r)  ; ?o on [?r] or {?r}
    (soaked ?o ?r)  ; ?o soaked [?r] or {?r}
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

  (:action beat_u18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (available egg)
      (available whisk)
      (in egg bowl)
      (is-cracked egg)
    )
    :effect (and
      (is-beaten egg)
      (not (is-cracked egg))
    )
  )

  (:action pour_u19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available egg)
      (available milk)
      (contains bowl egg)
      (in egg bowl)
      (in milk carton)
      (is-beaten egg)
    )
    :effect (and
      (contains bowl milk)
      (in milk bowl)
      (not (in milk carton))
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

  (:action beat_u39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (available egg)
      (available fork)
      (in egg bowl)
      (is-cracked egg)
    )
    :effect (and
      (is-beaten egg)
      (not (is-cracked egg))
    )
  )

  (:action pour_u40
    ; unit 40: pour* from 05-french_toast.foon:37
    ; pour: bowl (contains {egg, milk}), cinnamon (ground), vanilla extract (liquid) -> bowl (contains {cinnamon, egg, milk, vanilla extract}), cinnamon (in [bowl]), vanilla extract (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available cinnamon)
      (available vanilla_extract)
      (contains bowl egg)
      (contains bowl milk)
      (is-ground cinnamon)
      (is-liquid vanilla_extract)
    )
    :effect (and
      (contains bowl cinnamon)
      (contains bowl vanilla_extract)
      (in cinnamon bowl)
      (in vanilla_extract bowl)
      (not (is-ground cinnamon))
      (not (is-liquid vanilla_extract))
    )
  )

  (:action mix_u41
    ; unit 41: mix from 05-french_toast.foon:51
    ; mix: bowl (contains {cinnamon, egg, milk, vanilla extract}), egg (beaten, in [bowl]), milk (in [bowl]), cinnamon (in [bowl]), vanilla extract (in [bowl]), fork -> bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla...
    :parameters ()
    :precondition (and
      (available bowl)
      (available cinnamon)
      (available egg)
      (available fork)
      (available milk)
      (available vanilla_extract)
      (contains bowl cinnamon)
      (contains bowl egg)
      (contains bowl milk)
      (contains bowl vanilla_extract)
      (in cinnamon bowl)
      (in egg bowl)
      (in milk bowl)
      (in vanilla_extract bowl)
      (is-beaten egg)
    )
    :effect (and
      (available custard)
      (contains bowl custard)
      (contains custard cinnamon)
      (contains custard egg)
      (contains custard milk)
      (contains custard vanilla_extract)
      (in custard bowl)
      (not (contains bowl cinnamon))
      (not (contains bowl egg))
      (not (contains bowl milk))
      (not (contains bowl vanilla_extract))
    )
  )

  (:action dip_u42
    ; unit 42: dip from 05-french_toast.foon:71
    ; dip: bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl]), bread (sliced) -> bread (sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (available bowl)
      (available bread)
      (available custard)
      (contains bowl custard)
      (contains custard cinnamon)
      (contains custard egg)
      (contains custard milk)
      (contains custard vanilla_extract)
      (in custard bowl)
      (is-sliced bread)
    )
    :effect (and
      (soaked bread custard)
    )
  )

  (:action pick-and-place_u43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (available bread)
      (available butter)
      (available frying_pan)
      (contains frying_pan butter)
      (in butter frying_pan)
      (is-melted butter)
      (is-sliced bread)
      (on frying_pan stove)
      (soaked bread custard)
    )
    :effect (and
      (contains frying_pan bread)
      (in bread frying_pan)
    )
  )

  (:action fry_u44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (available bread)
      (available frying_pan)
      (available spatula)
      (available stove)
      (contains frying_pan bread)
      (contains frying_pan butter)
      (in bread frying_pan)
      (is-on stove)
      (is-sliced bread)
      (on frying_pan stove)
      (soaked bread custard)
    )
    :effect (and
      (available french_toast)
      (contains frying_pan french_toast)
      (in french_toast frying_pan)
      (is-cooked french_toast)
      (not (contains frying_pan bread))
      (not (contains frying_pan butter))
    )
  )

  (:action pick-and-place_u45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (available french_toast)
      (available frying_pan)
      (available plate)
      (available spatula)
      (contains frying_pan french_toast)
      (in french_toast frying_pan)
      (is-cooked french_toast)
      (is-empty plate)
      (on frying_pan stove)
    )
    :effect (and
      (contains plate french_toast)
      (on french_toast plate)
      (not (in french_toast frying_pan))
      (not (is-empty plate))
    )
  )

  (:action pour_u46
    ; unit 46: pour from 05-french_toast.foon:175
    ; pour: plate (contains {french toast}), french toast (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {french toast, maple syrup}), french toast (cooked, on [plate], topped {maple syrup}), maple syrup (on [french toast])
    :parameters ()
    :precondition (and
      (available french_toast)
      (available maple_syrup)
      (available plate)
      (contains plate french_toast)
      (in maple_syrup bottle)
      (is-cooked french_toast)
      (on french_toast plate)
    )
    :effect (and
      (contains plate maple_syrup)
      (on maple_syrup french_toast)
      (topped french_toast maple_syrup)
      (not (in maple_syrup bottle))
    )
  )
)
