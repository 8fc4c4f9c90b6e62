; foon2pddl, encoding state, level 3: 28 of 101 units after relevance pruning
; goal: fruit salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-b8632e42)
  (:requirements :strips)
  (:constants
    avocado
    baking_powder
    banana
    bowl
    carton
    cutting_board
    electric_mixer
    flour
    fork
    fruit_salad
    heavy_cream
    honey
    jar
    juicer
    knife
    lime
    lime_juice
    mixing_bowl
    salt
    spoon
    strawberry
    sugar
    whipped_cream
    whisk
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-empty ?o)  ; ?o is empty
    (is-granulated ?o)  ; ?o is granulated
    (is-halved ?o)  ; ?o is halved
    (is-mashed ?o)  ; ?o is mashed
    (is-off ?o)  ; ?o is off
    (is-on ?o)  ; ?o is on
    (is-peeled ?o)  ; ?o is peeled
    (is-powder ?o)  ; ?o is powder
    (is-scooped ?o)  ; ?o is scooped
    (is-sliced ?o)  ; ?o is sliced
    (is-squeezed ?o)  ; ?o is squeezed
    (is-whipped ?o)  ; ?o is whipped
    (is-whole ?o)  ; ?o is whole
    (attached_to ?o ?r)  ; ?o attached to [?r] or {?r}
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (on ?o ?r)  ; ?o on [?r] or {?r}
    (topped ?o ?r)  ; ?o topped [?r] or {?r}
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

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available avocado)
      (available cutting_board)
      (is-empty cutting_board)
      (is-whole avocado)
    )
    :effect (and
      (contains cutting_board avocado)
      (on avocado cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available avocado)
      (available cutting_board)
      (available knife)
      (contains cutting_board avocado)
      (is-whole avocado)
      (on avocado cutting_board)
    )
    :effect (and
      (is-halved avocado)
      (not (is-whole avocado))
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (available avocado)
      (available bowl)
      (available spoon)
      (is-empty bowl)
      (is-halved avocado)
      (on avocado cutting_board)
    )
    :effect (and
      (contains bowl avocado)
      (in avocado bowl)
      (is-scooped avocado)
      (not (is-empty bowl))
      (not (is-halved avocado))
      (not (on avocado cutting_board))
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (available avocado)
      (available fork)
      (in avocado bowl)
      (is-scooped avocado)
    )
    :effect (and
      (is-mashed avocado)
      (not (is-scooped avocado))
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available lime)
      (is-empty cutting_board)
      (is-whole lime)
    )
    :effect (and
      (contains cutting_board lime)
      (on lime cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available lime)
      (contains cutting_board lime)
      (is-whole lime)
      (on lime cutting_board)
    )
    :effect (and
      (is-halved lime)
      (not (is-whole lime))
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (available juicer)
      (available lime)
      (is-empty juicer)
      (is-halved lime)
      (on lime cutting_board)
    )
    :effect (and
      (available lime_juice)
      (contains juicer lime_juice)
      (in lime_juice juicer)
      (is-squeezed lime)
      (not (is-empty juicer))
      (not (is-halved lime))
      (not (on lime cutting_board))
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (available avocado)
      (available bowl)
      (available juicer)
      (available lime_juice)
      (contains bowl avocado)
      (contains juicer lime_juice)
      (in avocado bowl)
      (in lime_juice juicer)
      (is-mashed avocado)
    )
    :effect (and
      (contains bowl lime_juice)
      (in lime_juice bowl)
      (not (in lime_juice juicer))
    )
  )

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available strawberry)
      (is-empty cutting_board)
      (is-whole strawberry)
    )
    :effect (and
      (contains cutting_board strawberry)
      (on strawberry cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available strawberry)
      (contains cutting_board strawberry)
      (is-whole strawberry)
      (on strawberry cutting_board)
    )
    :effect (and
      (is-sliced strawberry)
      (not (is-whole strawberry))
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters ()
    :precondition (and
      (available banana)
      (is-whole banana)
    )
    :effect (and
      (is-peeled banana)
      (not (is-whole banana))
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (available banana)
      (available cutting_board)
      (is-empty cutting_board)
      (is-peeled banana)
    )
    :effect (and
      (contains cutting_board banana)
      (on banana cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available banana)
      (available cutting_board)
      (available knife)
      (contains cutting_board banana)
      (is-peeled banana)
      (on banana cutting_board)
    )
    :effect (and
      (is-sliced banana)
      (not (is-peeled banana))
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available strawberry)
      (is-empty bowl)
      (is-sliced strawberry)
      (on strawberry cutting_board)
    )
    :effect (and
      (contains bowl strawberry)
      (in strawberry bowl)
      (not (is-empty bowl))
      (not (on strawberry cutting_board))
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available banana)
      (available bowl)
      (contains bowl strawberry)
      (is-sliced banana)
      (on banana cutting_board)
    )
    :effect (and
      (contains bowl banana)
      (in banana bowl)
      (not (on banana cutting_board))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available juicer)
      (available lime_juice)
      (contains bowl banana)
      (contains bowl strawberry)
      (contains juicer lime_juice)
      (in lime_juice juicer)
    )
    :effect (and
      (contains bowl lime_juice)
      (in lime_juice bowl)
      (not (in lime_juice juicer))
    )
  )

  (:action pour_u97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available honey)
      (contains bowl banana)
      (contains bowl lime_juice)
      (contains bowl strawberry)
      (in honey jar)
    )
    :effect (and
      (contains bowl honey)
      (in honey bowl)
      (not (in honey jar))
    )
  )

  (:action mix_u98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters ()
    :precondition (and
      (available banana)
      (available bowl)
      (available honey)
      (available lime_juice)
      (available spoon)
      (available strawberry)
      (contains bowl banana)
      (contains bowl honey)
      (contains bowl lime_juice)
      (contains bowl strawberry)
      (in banana bowl)
      (in honey bowl)
      (in lime_juice bowl)
      (in strawberry bowl)
      (is-sliced banana)
      (is-sliced strawberry)
    )
    :effect (and
      (available fruit_salad)
      (contains bowl fruit_salad)
      (contains fruit_salad banana)
      (contains fruit_salad honey)
      (contains fruit_salad lime_juice)
      (contains fruit_salad strawberry)
      (in fruit_salad bowl)
      (not (contains bowl banana))
      (not (contains bowl honey))
      (not (contains bowl lime_juice))
      (not (contains bowl strawberry))
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

  (:action scoop_u100
    ; unit 100: scoop from 09-fruit_salad.foon:199
    ; scoop: bowl (contains {fruit salad}), fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl]), mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spoon -> bowl (contains {fruit salad, whi...
    :parameters ()
    :precondition (and
      (available bowl)
      (available fruit_salad)
      (available mixing_bowl)
      (available spoon)
      (available whipped_cream)
      (contains bowl fruit_salad)
      (contains fruit_salad banana)
      (contains fruit_salad honey)
      (contains fruit_salad lime_juice)
      (contains fruit_salad strawberry)
      (contains mixing_bowl whipped_cream)
      (in fruit_salad bowl)
      (in whipped_cream mixing_bowl)
      (is-whipped whipped_cream)
    )
    :effect (and
      (contains bowl whipped_cream)
      (on whipped_cream fruit_salad)
      (topped fruit_salad whipped_cream)
      (not (in whipped_cream mixing_bowl))
    )
  )
)
