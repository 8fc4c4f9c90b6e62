; foon2pddl, encoding state, level 3: 10 of 101 units after relevance pruning
; goal: whipped cream (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-e6102523)
  (:requirements :strips)
  (:constants
    baking_powder
    bowl
    carton
    electric_mixer
    flour
    heavy_cream
    mixing_bowl
    salt
    spatula
    sugar
    whipped_cream
    whisk
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-empty ?o)  ; ?o is empty
    (is-granulated ?o)  ; ?o is granulated
    (is-off ?o)  ; ?o is off
    (is-on ?o)  ; ?o is on
    (is-powder ?o)  ; ?o is powder
    (is-whipped ?o)  ; ?o is whipped
    (attached_to ?o ?r)  ; ?o attached to [?r] or {?r}
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (with ?o ?r)  ; ?o with [?r] or {?r}
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

  (:action attach_u11
    ; unit 11: attach from 02-whipped_cream.foon:23
    ; attach: mixing bowl (contains {heavy cream, sugar}), electric mixer (off) -> mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (available electric_mixer)
      (available mixing_bowl)
      (contains mixing_bowl heavy_cream)
      (contains mixing_bowl sugar)
      (is-off electric_mixer)
    )
    :effect (and
      (attached_to mixing_bowl electric_mixer)
      (with electric_mixer mixing_bowl)
    )
  )

  (:action turn_on_u12
    ; unit 12: turn on from 02-whipped_cream.foon:35
    ; turn on: electric mixer (off, with [mixing bowl]) -> electric mixer (on, with [mixing bowl])
    :parameters ()
    :precondition (and
      (available electric_mixer)
      (is-off electric_mixer)
      (with electric_mixer mixing_bowl)
    )
    :effect (and
      (is-on electric_mixer)
      (not (is-off electric_mixer))
    )
  )

  (:action mix_u13
    ; unit 13: mix from 02-whipped_cream.foon:43
    ; mix: electric mixer (on, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]) -> electric mixer (on, with [mixing bowl]), mixing bowl (at...
    :parameters ()
    :precondition (and
      (attached_to mixing_bowl electric_mixer)
      (available electric_mixer)
      (available heavy_cream)
      (available mixing_bowl)
      (available sugar)
      (contains mixing_bowl heavy_cream)
      (contains mixing_bowl sugar)
      (in heavy_cream mixing_bowl)
      (in sugar mixing_bowl)
      (is-on electric_mixer)
      (with electric_mixer mixing_bowl)
    )
    :effect (and
      (available whipped_cream)
      (contains mixing_bowl whipped_cream)
      (in whipped_cream mixing_bowl)
      (is-whipped whipped_cream)
      (not (contains mixing_bowl heavy_cream))
      (not (contains mixing_bowl sugar))
    )
  )

  (:action turn_off_u14
    ; unit 14: turn off from 02-whipped_cream.foon:64
    ; turn off: electric mixer (on, with [mixing bowl]) -> electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (available electric_mixer)
      (is-on electric_mixer)
      (with electric_mixer mixing_bowl)
    )
    :effect (and
      (is-off electric_mixer)
      (not (is-on electric_mixer))
    )
  )

  (:action scoop_u16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters ()
    :precondition (and
      (available bowl)
      (available mixing_bowl)
      (available spatula)
      (available whipped_cream)
      (contains mixing_bowl whipped_cream)
      (in whipped_cream mixing_bowl)
      (is-empty bowl)
      (is-whipped whipped_cream)
    )
    :effect (and
      (contains bowl whipped_cream)
      (in whipped_cream bowl)
      (not (in whipped_cream mixing_bowl))
      (not (is-empty bowl))
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

  (:action whisk_u99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters ()
    :precondition (and
      (available heavy_cream)
      (available mixing_bowl)
      (available sugar)
      (available whisk)
      (contains mixing_bowl heavy_cream)
      (contains mixing_bowl sugar)
      (in heavy_cream mixing_bowl)
      (in sugar mixing_bowl)
    )
    :effect (and
      (available whipped_cream)
      (contains mixing_bowl whipped_cream)
      (in whipped_cream mixing_bowl)
      (is-whipped whipped_cream)
      (not (contains mixing_bowl heavy_cream))
      (not (contains mixing_bowl sugar))
    )
  )
)
